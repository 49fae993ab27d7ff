// native_baseline.hpp - the native C++ baseline that `ggx bench` times against the OpenCL
// kernels: the same sampling math written as plain scalar float C++ (what a user would otherwise
// write), compiled -O3 -march=native and run on `threads` std::threads.  Method ids and
// conventions follow ggxref::Method and docs/MATH.md; uniforms are the project's Philox stream.
#pragma once

#include <cstdint>

namespace ggxnative {

enum class Method { ndf, heitz, heitz2017, caps, caps_iso, bounded };  // same order as ggxref::Method

// What one timed job does per sample k:
//   write_m_pdf_m: tangent-space view; write m (planar: m[k], m[count+k], m[2count+k]) and pdf_m[k]
//                  (pdf of m per steradian: D(m) mz for ndf, 4 (i.m) pdf_o for the VNDF family).
//   furnace_sum:   tangent-space view; write nothing; return the sum of the white-furnace weights
//                  D G2 / (4 iz) / pdf_o (Fresnel 1), 0 for a wasted sample.
//   world_space_o: per-sample world-space normal n[k] and view i[k] (planar inputs); write o in
//                  world space (planar).  Classic methods go through the branchless orthonormal
//                  basis of Duff et al. 2017; caps-iso works in world space directly.
enum class Job { write_m_pdf_m, furnace_sum, world_space_o };

struct Setup {
    Method method;
    Job job;
    float alpha_x, alpha_y;  // caps-iso and world_space_o are isotropic: they read alpha_x only
    float view[3];           // unit tangent-space view (z >= 0) for the two tangent-space jobs
    std::uint64_t seed, count;
    int threads;  // [0, count) is split into `threads` contiguous ranges (values < 1 mean 1)
};

struct Buffers {
    float* m = nullptr;                // 3 * count floats, planar (write_m_pdf_m)
    float* pdf_m = nullptr;            // count floats (write_m_pdf_m)
    float* o = nullptr;                // 3 * count floats, planar (world_space_o)
    const float* normals = nullptr;    // 3 * count floats, planar, unit (world_space_o)
    const float* views = nullptr;      // 3 * count floats, planar, unit (world_space_o)
};

// Runs one job; returns the furnace sum for Job::furnace_sum, else 0.  The result does not
// depend on `threads`: the sum is accumulated in fixed blocks of samples and the block sums are
// added in order.
double run(const Setup&, const Buffers&);

// The hand-vectorized "ceiling" (native_vectorized.cpp): the furnace sum of isotropic caps
// sampling with 16-lane GCC vectors (AVX-512 where available), vector Philox and a polynomial
// sincos.  Same uniforms and weights as run() with Method::caps, Job::furnace_sum, up to float
// rounding.
double furnace_caps_vectorized(std::uint64_t seed, std::uint64_t count, float alpha, const float view[3],
                               int threads);

const char* method_name(Method);  // "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"
const char* job_name(Job);        // "write_m_pdf_m", "furnace_sum", "world_space_o"

}  // namespace ggxnative
