// text_and_ply_writers.cpp - the .csv and .ply sample writers, and the
// format choice by extension.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>

#include "cli_values.hpp"
#include "npy_file.hpp"
#include "sample_writer.hpp"

namespace ggxapp {

namespace {

class NpySampleWriter : public SampleWriter {
public:
    NpySampleWriter(const std::string& path, std::uint64_t rows, std::size_t columns) : npy_(path, rows, columns) {}
    void append(const std::vector<float>& rows) override { npy_.append(rows); }
    void commit() override { npy_.commit(); }

private:
    NpyWriter npy_;
};

class CsvWriter : public SampleWriter {
public:
    CsvWriter(const std::string& path, const std::vector<std::string>& columns) : file_(path), columns_(columns.size())
    {
        std::string header;
        for (const std::string& name : columns)
            header += (header.empty() ? "" : ",") + name;
        header += "\n";
        file_.write(header.data(), header.size());
    }

    void append(const std::vector<float>& rows) override
    {
        // The shortest text that reads back as the same float (std::to_chars), about 15 bytes each.
        std::string text(rows.size() * 16, '\0');
        char* at = text.data();
        for (std::size_t k = 0; k < rows.size(); ++k) {
            at = std::to_chars(at, text.data() + text.size(), rows[k]).ptr;
            *at++ = (k + 1) % columns_ ? ',' : '\n';
        }
        file_.write(text.data(), std::size_t(at - text.data()));
    }
    void commit() override { file_.commit(); }

private:
    AtomicFile file_;
    std::size_t columns_;
};

// Viridis-like color of t in [0, 1] (five control points of matplotlib's viridis, interpolated).
void color_of(float t, unsigned char rgb[3])
{
    static const float stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    t = std::fmin(std::fmax(t, 0.0f), 1.0f) * 4.0f;
    int k = std::min(int(t), 3);
    float f = t - k;
    for (int c = 0; c < 3; ++c)
        rgb[c] = (unsigned char)std::lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]));
}

// Vertices (x, y, z) colored by log10(pdf) over [-2, 3] (pdf 0.01 .. 1000 per steradian).
class PlyWriter : public SampleWriter {
public:
    PlyWriter(const std::string& path, std::uint64_t rows) : file_(path)
    {
        std::string header = "ply\nformat binary_little_endian 1.0\n"
                             "comment ggxcl sample directions on the unit sphere, colored by log10(pdf) in [-2, 3]\n"
                             "element vertex " + std::to_string(rows) +
                             "\nproperty float x\nproperty float y\nproperty float z\n"
                             "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
        file_.write(header.data(), header.size());
    }

    void append(const std::vector<float>& rows) override
    {
        std::vector<unsigned char> bytes(rows.size() / 4 * 15);
        for (std::size_t j = 0; j < rows.size() / 4; ++j) {
            std::memcpy(&bytes[15 * j], &rows[4 * j], 12);
            float pdf = rows[4 * j + 3];
            float t = pdf > 0.0f ? (std::log10(pdf) + 2.0f) / 5.0f : 0.0f;
            color_of(t, &bytes[15 * j + 12]);
        }
        file_.write(bytes.data(), bytes.size());
    }
    void commit() override { file_.commit(); }

private:
    AtomicFile file_;
};

bool ends_with(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

Format format_of(const std::string& flag, const std::string& path)
{
    if (ends_with(path, ".npy")) return Format::npy;
    if (ends_with(path, ".csv")) return Format::csv;
    if (ends_with(path, ".ply")) return Format::ply;
    throw UsageError(flag, path, "a path ending in .npy, .csv or .ply");
}

std::unique_ptr<SampleWriter> make_writer(Format format, const std::string& path, std::uint64_t rows,
                                          const std::vector<std::string>& columns)
{
    switch (format) {
    case Format::csv: return std::make_unique<CsvWriter>(path, columns);
    case Format::ply: return std::make_unique<PlyWriter>(path, rows);
    case Format::npy: break;
    }
    return std::make_unique<NpySampleWriter>(path, rows, columns.size());
}

} // namespace ggxapp
