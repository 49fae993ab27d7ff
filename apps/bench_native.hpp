// bench_native.hpp - `ggx bench`'s side-by-side baselines on the host CPU:
// the plain C++ float code of bench/native (what a user would otherwise
// write, -O3 -march=native, on `threads` threads) for each method and job,
// timed by wall clock (median of repeats after a warm-up), its numerical
// error against the reference (m and pdf_m, the fields it writes), and the
// hand-vectorized ceiling of the fused caps estimator.
#pragma once

#include <cstdint>

#include <ggxcl/ggxcl.hpp>

#include "bench_accuracy.hpp"
#include "bench_speed.hpp"

namespace ggxapp {

struct NativeSetup {
    std::uint32_t count = 1u << 22;
    int threads = 2, repeats = 7;
    float alpha = 0.3f;
    ggxcl::Vec3 view;
};

Timing native_timing(ggxcl::Method method, BenchJob job, const NativeSetup& setup);

// The fused caps estimator, hand-vectorized: the machine's ceiling.
Timing native_ceiling_timing(const NativeSetup& setup);

NumericalError native_numerical_error(ggxcl::Method method);

} // namespace ggxapp
