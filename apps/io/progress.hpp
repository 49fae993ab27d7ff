// progress.hpp - a one-line progress bar on stderr for long jobs: shown
// only when stderr is a terminal and the job has run for over a second,
// redrawn at most ten times a second, and erased when the job ends.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace ggxapp {

class Progress {
public:
    Progress(std::string label, std::uint64_t total);
    ~Progress();
    void advance(std::uint64_t done);

private:
    using Clock = std::chrono::steady_clock;
    std::string label_;
    std::uint64_t total_;
    bool terminal_;
    bool drawn_ = false;
    Clock::time_point start_, last_draw_;
};

} // namespace ggxapp
