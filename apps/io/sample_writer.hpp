// sample_writer.hpp - the file formats `ggx sample` writes, chosen by the
// output's extension: .npy (float32, (N, columns)), .csv (a header line of
// column names, then one row per sample) and .ply (a binary point cloud of
// unit directions colored by their pdf, for MeshLab and Blender).  Every
// writer streams rows in chunks into a temporary file renamed on commit.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace ggxapp {

enum class Format { npy, csv, ply };

// The format of a path's extension; throws UsageError naming `flag` otherwise.
Format format_of(const std::string& flag, const std::string& path);

class SampleWriter {
public:
    virtual ~SampleWriter() = default;
    // Rows in file order, row-major, `columns` floats each.
    virtual void append(const std::vector<float>& rows) = 0;
    virtual void commit() = 0;
};

// .npy and .csv write the given columns; .ply writes columns (x, y, z, pdf)
// as a vertex and its color.
std::unique_ptr<SampleWriter> make_writer(Format format, const std::string& path, std::uint64_t rows,
                                          const std::vector<std::string>& columns);

} // namespace ggxapp
