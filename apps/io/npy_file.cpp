// npy_file.cpp - .npy writer and reader (format: numpy.lib.format, v1.0).
#include "npy_file.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <istream>
#include <regex>
#include <stdexcept>

namespace ggxapp {

std::string npy_header(std::uint64_t rows, std::uint64_t columns, const char* descr)
{
    std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
    std::size_t unpadded = 10 + dict.size() + 1;  // magic, version, length, dict, newline
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict += '\n';
    std::string header("\x93NUMPY\x01\x00", 8);
    header += char(dict.size() & 0xff);
    header += char(dict.size() >> 8);
    return header + dict;
}

NpyWriter::NpyWriter(const std::string& path, std::uint64_t rows, std::uint64_t columns)
    : file_(path), rows_(rows), columns_(columns)
{
    std::string header = npy_header(rows, columns);
    file_.write(header.data(), header.size());
}

void NpyWriter::append(const std::vector<float>& row_major)
{
    if (row_major.size() % columns_ != 0 || written_ + row_major.size() / columns_ > rows_)
        throw std::logic_error("NpyWriter: chunk does not fit the announced shape");
    file_.write(row_major.data(), row_major.size() * sizeof(float));
    written_ += row_major.size() / columns_;
}

void NpyWriter::commit()
{
    if (written_ != rows_)
        throw std::logic_error("NpyWriter: " + std::to_string(written_) + " of " + std::to_string(rows_) +
                               " rows written");
    file_.commit();
}

void write_npy_f64(const std::string& path, std::uint64_t rows, std::uint64_t columns, const std::vector<double>& data)
{
    if (data.size() != rows * columns)
        throw std::logic_error("write_npy_f64: data does not fit the shape");
    AtomicFile file(path);
    std::string header = npy_header(rows, columns, "<f8");
    file.write(header.data(), header.size());
    file.write(data.data(), data.size() * sizeof(double));
    file.commit();
}

NpyArray read_npy(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read '" + path + "'");
    return parse_npy(in, path);
}

namespace {

struct NpyHeader {
    std::string descr;                  // '<f4' or '<f8'
    std::uint64_t rows = 0, columns = 0;
    std::uint64_t data_bytes = 0;       // what follows the header in the file
};

// The header of a 2-D C-order little-endian float32 or float64 .npy; the
// stream is left at the first data byte.
NpyHeader parse_header(std::istream& in, const std::string& path)
{
    in.seekg(0, std::ios::end);
    const std::uint64_t size = std::uint64_t(in.tellg());
    in.seekg(0, std::ios::beg);
    char preamble[10];
    if (!in.read(preamble, 10) || std::memcmp(preamble, "\x93NUMPY\x01\x00", 8) != 0)
        throw std::runtime_error("'" + path + "' is not a version 1.0 .npy file");
    std::size_t length = std::uint8_t(preamble[8]) | (std::uint8_t(preamble[9]) << 8);
    std::string dict(length, '\0');
    in.read(dict.data(), length);
    static const std::regex shape(
        R"re(\{'descr': '(<f4|<f8)', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \}\s*)re");
    std::smatch match;
    if (!in || !std::regex_match(dict, match, shape))
        throw std::runtime_error("'" + path + "' is not a 2-D float32 or float64 C-order .npy file");
    NpyHeader header;
    header.descr = match[1];
    const std::string rows = match[2], columns = match[3];
    if (rows.size() > 19 || columns.size() > 19)  // beyond any file's size, and beyond stoull
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    header.rows = std::stoull(rows);
    header.columns = std::stoull(columns);
    header.data_bytes = size - std::min<std::uint64_t>(size, 10 + length);
    return header;
}

// Reads rows x columns values of type T (checked against the bytes left before allocating).
template <class T> std::vector<T> read_values(std::istream& in, const NpyHeader& header, const std::string& path)
{
    if (header.columns != 0 && header.rows > header.data_bytes / sizeof(T) / header.columns)
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    std::vector<T> values(header.rows * header.columns);
    if (!in.read(reinterpret_cast<char*>(values.data()), values.size() * sizeof(T)))
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    return values;
}

} // namespace

NpyArray parse_npy(std::istream& in, const std::string& path)
{
    NpyHeader header = parse_header(in, path);
    if (header.descr != "<f4")
        throw std::runtime_error("'" + path + "' is not a 2-D float32 C-order .npy file");
    NpyArray array;
    array.rows = header.rows;
    array.columns = header.columns;
    array.data = read_values<float>(in, header, path);
    return array;
}

NpyRowReader::NpyRowReader(const std::string& path) : path_(path), in_(path, std::ios::binary)
{
    if (!in_)
        throw std::runtime_error("cannot read '" + path + "'");
    NpyHeader header = parse_header(in_, path);
    if (header.descr != "<f4")
        throw std::runtime_error("'" + path + "' is not a 2-D float32 C-order .npy file");
    if (header.columns != 0 && header.rows > header.data_bytes / sizeof(float) / header.columns)
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    rows_ = header.rows;
    columns_ = header.columns;
}

bool NpyRowReader::next(std::vector<float>& chunk, std::uint64_t max_rows)
{
    const std::uint64_t n = std::min(max_rows, rows_ - done_);
    if (n == 0)
        return false;
    chunk.resize(n * columns_);
    if (!in_.read(reinterpret_cast<char*>(chunk.data()), std::streamsize(chunk.size() * sizeof(float))))
        throw std::runtime_error("'" + path_ + "' is shorter than its shape says");
    done_ += n;
    return true;
}

NpyDoubles read_npy_doubles(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read '" + path + "'");
    NpyHeader header = parse_header(in, path);
    NpyDoubles array;
    array.rows = header.rows;
    array.columns = header.columns;
    array.float64 = header.descr == "<f8";
    if (array.float64) {
        array.data = read_values<double>(in, header, path);
    } else {
        std::vector<float> floats = read_values<float>(in, header, path);
        array.data.assign(floats.begin(), floats.end());
    }
    return array;
}

} // namespace ggxapp
