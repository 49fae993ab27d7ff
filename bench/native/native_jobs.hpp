// native_jobs.hpp - the three timed jobs of the native baseline over one contiguous range of
// sample indices, each a plain loop around one sampler: write m and pdf_m, sum furnace weights,
// or sample o in world space from per-sample normals and views.
#pragma once

#include <cstdint>

#include "native_baseline.hpp"
#include "native_basis.hpp"
#include "native_sample_bounded.hpp"
#include "native_sample_caps.hpp"
#include "native_sample_caps_iso.hpp"
#include "native_sample_heitz.hpp"
#include "native_sample_ndf.hpp"
#include "native_uniforms.hpp"

namespace ggxnative {

// Furnace weights are summed per block of this many samples (blocks aligned on the sample index),
// and the block sums in index order, so the total does not depend on how ranges are threaded.
constexpr std::uint64_t furnace_block = 4096;

// Sample indices [begin, end) of one thread.
struct Range {
    std::uint64_t begin, end;
};

// A tangent-space sampler: Sample from (i, ax, ay, u1, u2).
using TangentSampler = Sample (*)(Vec3, float, float, float, float);

// caps-iso in tangent space: n = (0, 0, 1), alpha = ax.
inline Sample sample_caps_iso_tangent(Vec3 i, float ax, float, float u1, float u2)
{
    return sample_caps_iso({0.0f, 0.0f, 1.0f}, i, ax, u1, u2);
}

inline Vec3 load3(const float* p, std::uint64_t k, std::uint64_t count)
{
    return {p[k], p[k + count], p[k + 2 * count]};
}

inline void store3(float* p, std::uint64_t k, std::uint64_t count, Vec3 v)
{
    p[k] = v.x;
    p[k + count] = v.y;
    p[k + 2 * count] = v.z;
}

inline Vec3 setup_view(const Setup& setup) { return {setup.view[0], setup.view[1], setup.view[2]}; }

// The loops copy the parameters into locals: a float store could otherwise alias setup.alpha_x,
// and the compiler would reload it, and redo everything that depends on it, every sample.
template <TangentSampler sample>
void write_m_pdf_m(const Setup& setup, const Buffers& out, Range range)
{
    const Vec3 i = setup_view(setup);
    const float ax = setup.alpha_x, ay = setup.alpha_y;
    const std::uint64_t seed = setup.seed, count = setup.count;
    float* m = out.m;
    float* pdf_m = out.pdf_m;
    for (std::uint64_t k = range.begin; k < range.end; ++k) {
        Uniforms u = uniforms(seed, k);
        Sample s = sample(i, ax, ay, u.u1, u.u2);
        store3(m, k, count, s.m);
        pdf_m[k] = s.pdf_m;
    }
}

// Writes the sum of the weights of block b into block_sums[b] for each block in the range
// (range ends are block-aligned, except the last at count).
template <TangentSampler sample>
void furnace_sum(const Setup& setup, Range range, double* block_sums)
{
    const Vec3 i = setup_view(setup);
    const float ax = setup.alpha_x, ay = setup.alpha_y;
    const std::uint64_t seed = setup.seed;
    for (std::uint64_t block = range.begin; block < range.end; block += furnace_block) {
        std::uint64_t block_end = block + furnace_block < range.end ? block + furnace_block : range.end;
        double sum = 0.0;
        for (std::uint64_t k = block; k < block_end; ++k) {
            Uniforms u = uniforms(seed, k);
            sum += sample(i, ax, ay, u.u1, u.u2).weight;
        }
        block_sums[block / furnace_block] = sum;
    }
}

// Classic methods: into the Duff basis of n, sample in tangent space, o back to world space.
template <TangentSampler sample>
Vec3 world_o_through_basis(Vec3 n, Vec3 i, float alpha, float u1, float u2)
{
    Basis basis = make_basis(n);
    Sample s = sample(basis.to_local(i), alpha, alpha, u1, u2);
    return basis.to_world(s.o);
}

inline Vec3 world_o_caps_iso(Vec3 n, Vec3 i, float alpha, float u1, float u2)
{
    return sample_caps_iso(n, i, alpha, u1, u2).o;
}

using WorldSampler = Vec3 (*)(Vec3, Vec3, float, float, float);

template <WorldSampler sample_o>
void world_space_o(const Setup& setup, const Buffers& buffers, Range range)
{
    const float alpha = setup.alpha_x;
    const std::uint64_t seed = setup.seed, count = setup.count;
    const float* normals = buffers.normals;
    const float* views = buffers.views;
    float* o = buffers.o;
    for (std::uint64_t k = range.begin; k < range.end; ++k) {
        Uniforms u = uniforms(seed, k);
        Vec3 n = load3(normals, k, count);
        Vec3 i = load3(views, k, count);
        store3(o, k, count, sample_o(n, i, alpha, u.u1, u.u2));
    }
}

}  // namespace ggxnative
