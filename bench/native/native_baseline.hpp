// native_baseline.hpp - the native C++ baseline that `ggx bench` times against the OpenCL
// kernels: the device headers of kernels/ (the samplers, Philox, the basis of world space)
// compiled by the host compiler, in the plain loops a C++ user writes, -O3 -march=native, on
// `threads` std::threads; and the same loop vectorized by the compiler (#pragma omp simd).
// Methods are the ids of the project's list of methods (GGX_METHOD_* of kernels/ggx_contract.h).
#pragma once

#include <cstdint>
#include <string>

namespace ggxnative {

// What one timed job does per sample k, with the uniforms of Philox sample k of the seed:
//   write_m_pdf_m: tangent-space view; write m (planar: m[k], m[count+k], m[2count+k]) and pdf_m[k].
//   furnace_sum:   tangent-space view; write nothing; return the sum of the white-furnace weights.
//   world_space_o: per-sample world-space normal n[k] and view i[k] (planar inputs); write o in
//                  world space (planar), through ggx_sample_world (a basis around n; caps-iso none).
enum class Job { write_m_pdf_m, furnace_sum, world_space_o };

struct Setup {
    int method;  // GGX_METHOD_* id
    Job job;
    float alpha_x, alpha_y;  // world_space_o is isotropic: it reads alpha_x only
    float view[3];           // unit tangent-space view for the two tangent-space jobs
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

// furnace_sum of `setup` (tangent space) with the loop vectorized by the compiler
// (native_vectorized.cpp): the same device functions, `#pragma omp simd` over the samples.
double furnace_vectorized(const Setup&);

int method_count();
const char* method_name(int method);  // "ndf", ..., or "?" for no method id
int method_id(const std::string& name);  // -1 for no method's name
const char* job_name(Job);            // "write_m_pdf_m", "furnace_sum", "world_space_o"

}  // namespace ggxnative
