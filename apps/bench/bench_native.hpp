// bench_native.hpp - `ggx bench`'s side-by-side baselines on the host CPU:
// bench/native's plain C++ loops around the device headers of kernels/
// (what a C++ user writes, -O3 -march=native, on `threads` threads) for
// each method and job,
// timed by wall clock (median of repeats after a warm-up), its numerical
// error against the reference (m and pdf_m, the fields it writes), and the
// fused estimator with its loop vectorized by the compiler (omp simd).
//
// The baseline runs in the child process ggx-native, so that no
// -march=native code is linked into `ggx`: found through $GGX_NATIVE, else
// next to the running `ggx`, else in ../libexec/ggxcl relative to it.  When
// it is missing or fails, these functions throw NativeBaselineError, and
// the bench goes on without its native rows.
#pragma once

#include <cstdint>
#include <stdexcept>

#include <ggxcl/ggxcl.hpp>

#include "bench_accuracy.hpp"
#include "bench_speed.hpp"

namespace ggxapp {

// ggx-native not found, not startable, failed or printed something unexpected;
// what() says which ("ggx-native not found: set GGX_NATIVE (...)", or the
// command and what went wrong).
struct NativeBaselineError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct NativeSetup {
    std::uint32_t count = 1u << 22;
    int threads = 2, repeats = 7;
    float alpha = 0.3f;
    ggxcl::Vec3 view;
};

Timing native_timing(ggxcl::Method method, BenchJob job, const NativeSetup& setup);

// The fused estimator of `method`, its loop vectorized by the compiler.
Timing native_vectorized_timing(ggxcl::Method method, const NativeSetup& setup);

NumericalError native_numerical_error(ggxcl::Method method);

} // namespace ggxapp
