// atomic_file.cpp - write to a temporary file, rename on success.
#include "atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

namespace ggxapp {

namespace {
std::runtime_error io_error(const std::string& what, const std::string& path)
{
    return std::runtime_error("cannot " + what + " '" + path + "': " + std::strerror(errno));
}
} // namespace

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temp_path_(path_ + ".tmp-" + std::to_string(::getpid()))
{
    file_ = std::fopen(temp_path_.c_str(), "wb");
    if (!file_)
        throw io_error("write", path_);
}

AtomicFile::~AtomicFile()
{
    if (file_) {
        std::fclose(file_);
        std::remove(temp_path_.c_str());
    }
}

void AtomicFile::write(const void* data, std::size_t bytes)
{
    if (bytes && std::fwrite(data, 1, bytes, file_) != bytes)
        throw io_error("write", path_);
}

void AtomicFile::commit()
{
    bool flushed = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
    bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!flushed || !closed || std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        std::runtime_error error = io_error("write", path_);
        std::remove(temp_path_.c_str());
        throw error;
    }
}

void write_text_file(const std::string& path, const std::string& text)
{
    AtomicFile file(path);
    file.write(text.data(), text.size());
    file.commit();
}

} // namespace ggxapp
