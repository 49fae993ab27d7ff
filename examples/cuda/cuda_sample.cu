// cuda_sample.cu - ggxcl's samplers in a CUDA program: the directional albedo (white furnace,
// Fresnel 1) of a GGX surface, roughness 0.3, view at 60 degrees, estimated on the GPU by every
// method from 2^24 samples, with the largest difference between a sample's pdf and the pdf
// recomputed from its direction.  Every method estimates the same albedo (about 0.97).
//
// Build: nvcc -std=c++17 -O2 -I<prefix>/include/ggxcl/cl cuda_sample.cu -o cuda_sample
// (from the source tree: -Ikernels).  Exit status 1 on a CUDA error or when the estimates
// disagree (more than 1 % apart) or a pdf differs by more than 1e-3.
#include <cmath>
#include <cstdio>
#include <vector>

#include <cuda_runtime.h>

#include "ggx_cuda_furnace.cuh"

namespace {

bool ok(cudaError_t status, const char* what)
{
    if (status != cudaSuccess)
        std::fprintf(stderr, "cuda_sample: %s: %s\n", what, cudaGetErrorString(status));
    return status == cudaSuccess;
}

const char* const method_names[] = {
#define GGX_NAME(ID, identifier, name, ...) name,
    GGX_METHOD_LIST(GGX_NAME)
#undef GGX_NAME
};

}  // namespace

int main()
{
    const unsigned int threads = 1u << 16, per_thread = 256, block = 256;
    const float alpha = 0.3f, theta = 60.0f * 3.14159265f / 180.0f;
    const ggx_vec3 i = ggx_vec3_make(std::sin(theta), 0.0f, std::cos(theta));
    float *sums = nullptr, *errors = nullptr;
    if (!ok(cudaMalloc(&sums, threads * sizeof(float)), "cudaMalloc") ||
        !ok(cudaMalloc(&errors, threads * sizeof(float)), "cudaMalloc"))
        return 1;
    std::vector<float> host_sums(threads), host_errors(threads);
    std::vector<double> albedo;
    bool agree = true;
    for (int method = 0; method < GGX_METHOD_COUNT; ++method) {
        ggx_furnace_kernel<<<threads / block, block>>>(method, 1u, per_thread, i, alpha, threads, sums, errors);
        if (!ok(cudaGetLastError(), "launch") ||
            !ok(cudaMemcpy(host_sums.data(), sums, threads * sizeof(float), cudaMemcpyDeviceToHost), "copy") ||
            !ok(cudaMemcpy(host_errors.data(), errors, threads * sizeof(float), cudaMemcpyDeviceToHost), "copy"))
            return 1;
        double total = 0.0, worst = 0.0;
        for (unsigned int t = 0; t < threads; ++t)
            total += host_sums[t], worst = std::fmax(worst, host_errors[t]);
        albedo.push_back(total / (double(threads) * per_thread));
        std::printf("%-10s albedo %.5f, largest pdf difference %.2e\n", method_names[method], albedo.back(), worst);
        agree = agree && worst <= 1e-3 && std::fabs(albedo.back() - albedo.front()) <= 1e-2 * albedo.front();
    }
    cudaFree(sums);
    cudaFree(errors);
    return agree ? 0 : 1;
}
