// native_commands.hpp - the three commands of ggx-native, the child process through which
// `ggx bench` runs the -march=native baseline (see ggx_native_main.cpp for the protocol).
//   time:    ns per sample of one method and job, one line per timed repeat, after a warm-up;
//   vectorized: the same for the furnace job with its loop vectorized by the compiler;
//   write:   m (3 x count floats, planar) then pdf_m (count floats), raw float32 on stdout.
#pragma once

#include <cstdint>
#include <cstdio>

#include "native_baseline.hpp"

namespace ggxnative {

struct TimedRun {
    std::uint64_t count;
    int threads, repeats;
    float alpha;
    float view[3];
};

void time_job(int method, Job job, const TimedRun& run, std::FILE* out);
void time_vectorized(int method, const TimedRun& run, std::FILE* out);
void write_samples(const Setup& setup, std::FILE* out);

}  // namespace ggxnative
