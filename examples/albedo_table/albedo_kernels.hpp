// albedo_kernels.hpp - the example's own OpenCL kernels.  They include the
// ggxcl device headers (built with ggxcl::build_user_program, which puts
// them on the include path): the per-sample inputs the runtime's sampler
// reads, the reduction of the weights it wrote, and the same sums with the
// sampler called inside the kernel, as a renderer's own kernel would.
// A block is `block` consecutive samples of one cell; each work-item sums one.
#pragma once

namespace albedo {

inline const char* const albedo_kernels_source = R"CL(
#include "ggx_samplers.h"

// The view and roughness of cell c: cells[3 c] = view x, cells[3 c + 1] = view z, cells[3 c + 2] = alpha.
typedef struct {
    ggx_vec3 view;
    float alpha;
} cell_params;

cell_params cell_at(__global const float* cells, uint c)
{
    cell_params p;
    p.view = ggx_vec3_make(cells[3 * c], 0.0f, cells[3 * c + 1]);
    p.alpha = cells[3 * c + 2];
    return p;
}

// Planar per-sample views (3 planes) and roughness (2 planes, isotropic) of
// `count` samples from cell first_cell on, per_cell samples a cell.
__kernel void cell_inputs(uint first_cell, uint per_cell, uint count, __global const float* cells,
                          __global float* views, __global float* alphas)
{
    uint j = get_global_id(0);
    cell_params p = cell_at(cells, first_cell + j / per_cell);
    views[j] = p.view.x;
    views[j + count] = p.view.y;
    views[j + 2 * count] = p.view.z;
    alphas[j] = p.alpha;
    alphas[j + count] = p.alpha;
}

// Sums of the weights (and of their squares) of each block of the buffer.
__kernel void block_sums(uint block, __global const float* weights, __global float* sums,
                         __global float* squares)
{
    uint b = get_global_id(0);
    float sum = 0.0f, sum2 = 0.0f;
    for (uint k = 0; k < block; ++k) {
        float w = weights[b * block + k];
        sum += w;
        sum2 += w * w;
    }
    sums[b] = sum;
    squares[b] = sum2;
}

// The same sums drawn here: sample index first_cell * per_cell + b * block + k
// of stream `seed`, by the sampler of ALBEDO_METHOD (a build option).
__kernel void block_sums_inline(ulong seed, uint first_cell, uint per_cell, uint block,
                                __global const float* cells, __global float* sums, __global float* squares)
{
    uint b = get_global_id(0);
    cell_params p = cell_at(cells, first_cell + b * block / per_cell);
    ulong first = (ulong)first_cell * per_cell + (ulong)b * block;
    float sum = 0.0f, sum2 = 0.0f;
    for (uint k = 0; k < block; ++k) {
        float u1, u2;
        ggx_uniforms(seed, first + k, &u1, &u2);
        ggx_sample s = ggx_sample_method(ALBEDO_METHOD, ggx_vec3_make(0.0f, 0.0f, 1.0f), p.view, p.alpha,
                                         p.alpha, u1, u2);
        sum += s.weight;
        sum2 += s.weight * s.weight;
    }
    sums[b] = sum;
    squares[b] = sum2;
}
)CL";

} // namespace albedo
