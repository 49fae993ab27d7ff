// ggx_cuda_furnace.cuh - CUDA kernels calling ggxcl's device headers: each thread draws
// `per_thread` samples of one method (Philox uniforms, the samplers of ggx_samplers.h) and
// writes the sum of their white-furnace weights, and the largest relative difference between
// each sample's pdf and the pdf its method recomputes from (i, o) alone.  cuda_sample.cu runs
// them; the test suite compiles this file with clang alone (no CUDA toolkit).
#pragma once

#include "ggx_philox.h"
#include "ggx_samplers.h"

// Thread t draws samples t * per_thread .. (t + 1) * per_thread - 1 of stream `seed`.
__global__ void ggx_furnace_kernel(int method, unsigned int seed, unsigned int per_thread, ggx_vec3 i, float alpha,
                                   unsigned int threads, float* weight_sums, float* pdf_errors)
{
    const unsigned int t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= threads)
        return;
    const ggx_vec3 n = ggx_vec3_make(0.0f, 0.0f, 1.0f);
    float sum = 0.0f, worst = 0.0f;
    for (unsigned int k = 0; k < per_thread; ++k) {
        float u1, u2;
        ggx_uniforms(seed, (unsigned long long)t * per_thread + k, &u1, &u2);
        const ggx_sample s = ggx_sample_method(method, n, i, alpha, alpha, u1, u2);
        sum += s.weight;
        if (s.weight > 0.0f) {  // a usable sample: its pdf again from (i, o)
            const float again = ggx_pdf_method(method, n, i, s.o, alpha, alpha);
            worst = fmaxf(worst, fabsf(again - s.pdf_o) / s.pdf_o);
        }
    }
    weight_sums[t] = sum;
    pdf_errors[t] = worst;
}
