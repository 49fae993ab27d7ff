// native_jobs.hpp - the timed jobs of the native baseline over one contiguous range of sample
// indices: plain loops around the device functions of kernels/ (compiled as C++ through
// ggx_platform.h), what a C++ renderer writes: write m and pdf_m, sum furnace weights, or
// sample o in world space from per-sample normals and views.
#pragma once

#include <cstdint>

#include "ggx_philox.h"
#include "ggx_world.h"
#include "native_baseline.hpp"

namespace ggxnative {

// Furnace weights are summed per block of this many samples (blocks aligned on the sample index),
// and the block sums in index order, so the total does not depend on how ranges are threaded.
constexpr std::uint64_t furnace_block = 4096;

// Sample indices [begin, end) of one thread.
struct Range {
    std::uint64_t begin, end;
};

inline ggx_vec3 load3(const float* p, std::uint64_t k, std::uint64_t count)
{
    return ggx_vec3_make(p[k], p[k + count], p[k + 2 * count]);
}

inline void store3(float* p, std::uint64_t k, std::uint64_t count, ggx_vec3 v)
{
    p[k] = v.x;
    p[k + count] = v.y;
    p[k + 2 * count] = v.z;
}

inline ggx_vec3 setup_view(const Setup& setup) { return ggx_vec3_make(setup.view[0], setup.view[1], setup.view[2]); }

// Sample k of a tangent-space setup, as a bulk kernel draws it: Philox uniforms of (seed, k),
// the method's sampler through the dispatcher (folded to one sampler: `method` is a constant),
// the normal +z.
template <int method>
GGX_INLINE ggx_sample tangent_sample(std::uint64_t seed, std::uint64_t k, ggx_vec3 i, float ax, float ay)
{
    float u1, u2;
    ggx_uniforms(seed, k, &u1, &u2);
    return ggx_sample_method(method, ggx_vec3_make(0.0f, 0.0f, 1.0f), i, ax, ay, u1, u2);
}

// The loops copy the parameters into locals: a float store could otherwise alias setup.alpha_x,
// and the compiler would reload it, and redo everything that depends on it, every sample.
template <int method>
void write_m_pdf_m(const Setup& setup, const Buffers& out, Range range)
{
    const ggx_vec3 i = setup_view(setup);
    const float ax = setup.alpha_x, ay = setup.alpha_y;
    const std::uint64_t seed = setup.seed, count = setup.count;
    float* m = out.m;
    float* pdf_m = out.pdf_m;
    for (std::uint64_t k = range.begin; k < range.end; ++k) {
        ggx_sample s = tangent_sample<method>(seed, k, i, ax, ay);
        store3(m, k, count, s.m);
        pdf_m[k] = s.pdf_m;
    }
}

// Writes the sum of the weights of block b into block_sums[b] for each block in the range
// (range ends are block-aligned, except the last at count).
template <int method>
void furnace_sum(const Setup& setup, Range range, double* block_sums)
{
    const ggx_vec3 i = setup_view(setup);
    const float ax = setup.alpha_x, ay = setup.alpha_y;
    const std::uint64_t seed = setup.seed;
    for (std::uint64_t block = range.begin; block < range.end; block += furnace_block) {
        std::uint64_t block_end = block + furnace_block < range.end ? block + furnace_block : range.end;
        double sum = 0.0;
        for (std::uint64_t k = block; k < block_end; ++k)
            sum += tangent_sample<method>(seed, k, i, ax, ay).weight;
        block_sums[block / furnace_block] = sum;
    }
}

template <int method>
void world_space_o(const Setup& setup, const Buffers& buffers, Range range)
{
    const float alpha = setup.alpha_x;
    const std::uint64_t seed = setup.seed, count = setup.count;
    const float* normals = buffers.normals;
    const float* views = buffers.views;
    float* o = buffers.o;
    for (std::uint64_t k = range.begin; k < range.end; ++k) {
        float u1, u2;
        ggx_uniforms(seed, k, &u1, &u2);
        ggx_vec3 n = load3(normals, k, count), i = load3(views, k, count);
        store3(o, k, count, ggx_sample_world(method, n, i, alpha, u1, u2).o);
    }
}

}  // namespace ggxnative
