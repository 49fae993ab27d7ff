// atomic_file.cpp - write to a temporary file, rename on success.
#include "atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

namespace ggxapp {

namespace {

std::runtime_error io_error(const std::string& what, const std::string& path)
{
    return std::runtime_error("cannot " + what + " '" + path + "': " + std::strerror(errno));
}

// The temporary paths of the open AtomicFiles, readable from a signal handler:
// fixed slots of C strings, claimed and released with atomic pointers.
constexpr int max_open_files = 16;
std::atomic<const char*> open_temp_paths[max_open_files];

void remember_temp(const char* path)
{
    for (auto& slot : open_temp_paths) {
        const char* empty = nullptr;
        if (slot.compare_exchange_strong(empty, path))
            return;
    }
}

void forget_temp(const char* path)
{
    for (auto& slot : open_temp_paths) {
        const char* expected = path;
        if (slot.compare_exchange_strong(expected, nullptr))
            return;
    }
}

// Removes the temporary files still open (unlink is async-signal-safe).
extern "C" void remove_open_temps()
{
    for (auto& slot : open_temp_paths)
        if (const char* path = slot.load())
            ::unlink(path);
}

// ... then ends with the signal.
extern "C" void remove_temps_and_reraise(int signal)
{
    remove_open_temps();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

void install_interrupt_cleanup()
{
    for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGABRT})
        std::signal(signal, remove_temps_and_reraise);
    std::signal(SIGXFSZ, SIG_IGN);
    std::atexit(remove_open_temps);  // a library calling exit() mid-run (LLVM's fatal errors do)
}

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temp_path_(path_ + ".tmp-" + std::to_string(::getpid()))
{
    file_ = std::fopen(temp_path_.c_str(), "wb");
    if (!file_)
        throw io_error("write", path_);
    remember_temp(temp_path_.c_str());
}

AtomicFile::~AtomicFile()
{
    if (file_) {
        std::fclose(file_);
        std::remove(temp_path_.c_str());
    }
    forget_temp(temp_path_.c_str());
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
    forget_temp(temp_path_.c_str());
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
