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

NpyArray parse_npy(std::istream& in, const std::string& path)
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
    static const std::regex shape(R"re(\{'descr': '<f4', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \}\s*)re");
    std::smatch match;
    if (!in || !std::regex_match(dict, match, shape))
        throw std::runtime_error("'" + path + "' is not a 2-D float32 C-order .npy file");
    NpyArray array;
    const std::string rows = match[1], columns = match[2];
    if (rows.size() > 19 || columns.size() > 19)  // beyond any file's size, and beyond stoull
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    array.rows = std::stoull(rows);
    array.columns = std::stoull(columns);
    // The data must be exactly what remains after the header (checked before allocating).
    const std::uint64_t header = 10 + length, remaining = size - std::min(size, header);
    if (array.columns != 0 && array.rows > remaining / sizeof(float) / array.columns)
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    array.data.resize(array.rows * array.columns);
    if (!in.read(reinterpret_cast<char*>(array.data.data()), array.data.size() * sizeof(float)))
        throw std::runtime_error("'" + path + "' is shorter than its shape says");
    return array;
}

} // namespace ggxapp
