// npy_file.hpp - NumPy .npy version 1.0 files of little-endian float32 with
// shape (rows, columns), C order: a streaming writer (rows arrive in
// chunks, the file is renamed into place when complete) and readers (of
// float32 whole or rows at a time, and of float32 or float64 as doubles).
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "atomic_file.hpp"

namespace ggxapp {

// The 10-byte preamble plus the dictionary, padded to a multiple of 64 bytes.
std::string npy_header(std::uint64_t rows, std::uint64_t columns, const char* descr = "<f4");

class NpyWriter {
public:
    NpyWriter(const std::string& path, std::uint64_t rows, std::uint64_t columns);
    // Appends rows given row-major (rows_in_chunk * columns floats).
    void append(const std::vector<float>& row_major);
    // Checks that every announced row was written, then renames into place.
    void commit();

private:
    AtomicFile file_;
    std::uint64_t rows_, columns_, written_ = 0;
};

struct NpyArray {
    std::uint64_t rows = 0, columns = 0;
    std::vector<float> data;  // row-major
};

// Writes a whole float64 (rows, columns) array, e.g. counts beyond 2^24.
void write_npy_f64(const std::string& path, std::uint64_t rows, std::uint64_t columns, const std::vector<double>& data);

// Reads a float32 C-order 2-D .npy; throws std::runtime_error naming `path`
// on anything else (another format, a shape its bytes do not fill).
NpyArray read_npy(const std::string& path);
NpyArray parse_npy(std::istream& in, const std::string& name);

// A float32 C-order 2-D .npy read rows at a time, so that files larger than
// memory stream through a fixed buffer (ggx merge).  Throws like read_npy.
class NpyRowReader {
public:
    explicit NpyRowReader(const std::string& path);
    std::uint64_t rows() const { return rows_; }
    std::uint64_t columns() const { return columns_; }
    // Replaces `chunk` by the next rows (at most max_rows, row-major); false at the end.
    bool next(std::vector<float>& chunk, std::uint64_t max_rows);

private:
    std::string path_;
    std::ifstream in_;
    std::uint64_t rows_ = 0, columns_ = 0, done_ = 0;
};

// A float32 or float64 C-order 2-D .npy, its values as doubles (exact).
struct NpyDoubles {
    std::uint64_t rows = 0, columns = 0;
    bool float64 = false;      // the file's type
    std::vector<double> data;  // row-major
};
NpyDoubles read_npy_doubles(const std::string& path);

} // namespace ggxapp
