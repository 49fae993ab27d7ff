// progress.cpp - the stderr progress bar.
#include "progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace ggxapp {

Progress::Progress(std::string label, std::uint64_t total)
    : label_(std::move(label)), total_(total), terminal_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()),
      last_draw_(start_)
{
}

Progress::~Progress()
{
    if (drawn_)
        std::fprintf(stderr, "\r\033[K");
}

void Progress::advance(std::uint64_t done)
{
    Clock::time_point now = Clock::now();
    double elapsed = std::chrono::duration<double>(now - start_).count();
    if (!terminal_ || elapsed < 1.0 || now - last_draw_ < std::chrono::milliseconds(100))
        return;
    last_draw_ = now;
    drawn_ = true;
    double fraction = total_ ? double(done) / double(total_) : 1.0;
    const int width = 30;
    int filled = int(fraction * width);
    std::string bar = std::string(filled, '#') + std::string(width - filled, '.');
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.3g samples/s", label_.c_str(), bar.c_str(), 100.0 * fraction,
                 double(done) / elapsed);
    std::fflush(stderr);
}

} // namespace ggxapp
