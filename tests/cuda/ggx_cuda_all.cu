// ggx_cuda_all.cu - every sampler and pdf of the device headers called from CUDA __global__
// functions, three per method of the list (ggx_contract.h): its sample, its pdf of given
// directions, both in world space; and the Sobol points.  test_languages compiles it to PTX
// (clang without the CUDA toolkit, with cuda_shim.h; nvcc where installed) and checks one entry
// point per method and kind.  Outputs are planar: component c of item j at out[c * count + j].
#include "ggx_samplers.h"
#include "ggx_sobol.h"
#include "ggx_world.h"

__device__ inline unsigned int ggx_cuda_index() { return blockIdx.x * blockDim.x + threadIdx.x; }

__device__ inline void ggx_cuda_store(float* out, unsigned int count, unsigned int j, ggx_sample s)
{
    const float values[9] = {s.m.x, s.m.y, s.m.z, s.o.x, s.o.y, s.o.z, s.pdf_m, s.pdf_o, s.weight};
    for (unsigned int c = 0; c < 9; ++c)
        out[c * count + j] = values[c];
}

__device__ inline ggx_vec3 ggx_cuda_load3(const float* p, unsigned int count, unsigned int j)
{
    return ggx_vec3_make(p[j], p[count + j], p[2 * count + j]);
}

// Sample `first + j` of stream `seed` for a view i and normal n (tangent space: n = +z but for
// caps-iso); its pdf of directions o[j]; world-space samples for per-item normals and views.
#define GGX_CUDA_KERNELS(ID, identifier, name, ...)                                                                  \
    extern "C" __global__ void ggx_cuda_sample_##identifier(unsigned int seed, unsigned long long first,         \
                                                            unsigned int count, ggx_vec3 i, ggx_vec3 n, float ax, \
                                                            float ay, float* out)                               \
    {                                                                                                           \
        const unsigned int j = ggx_cuda_index();                                                                \
        if (j >= count)                                                                                         \
            return;                                                                                             \
        float u1, u2;                                                                                           \
        ggx_uniforms(seed, first + j, &u1, &u2);                                                                \
        ggx_cuda_store(out, count, j, ggx_sample_method(GGX_METHOD_##ID, n, i, ax, ay, u1, u2));                \
    }                                                                                                           \
    extern "C" __global__ void ggx_cuda_pdf_##identifier(unsigned int count, ggx_vec3 i, ggx_vec3 n, float ax,  \
                                                         float ay, const float* o, float* pdf)                  \
    {                                                                                                           \
        const unsigned int j = ggx_cuda_index();                                                                \
        if (j < count)                                                                                          \
            pdf[j] = ggx_pdf_method(GGX_METHOD_##ID, n, i, ggx_cuda_load3(o, count, j), ax, ay);                \
    }                                                                                                           \
    extern "C" __global__ void ggx_cuda_world_##identifier(unsigned int seed, unsigned int count, float alpha,   \
                                                           const float* normals, const float* views, float* out, \
                                                           float* pdf)                                          \
    {                                                                                                           \
        const unsigned int j = ggx_cuda_index();                                                                \
        if (j >= count)                                                                                         \
            return;                                                                                             \
        float u1, u2;                                                                                           \
        ggx_uniforms(seed, j, &u1, &u2);                                                                        \
        const ggx_vec3 n = ggx_cuda_load3(normals, count, j), i = ggx_cuda_load3(views, count, j);             \
        const ggx_sample s = ggx_sample_world(GGX_METHOD_##ID, n, i, alpha, u1, u2);                            \
        ggx_cuda_store(out, count, j, s);                                                                       \
        pdf[j] = ggx_pdf_world(GGX_METHOD_##ID, n, i, s.o, alpha);                                              \
    }

GGX_METHOD_LIST(GGX_CUDA_KERNELS)

// The Owen-scrambled Sobol points of stream `seed`, samples first .. first + count - 1.
extern "C" __global__ void ggx_cuda_sobol(unsigned int seed, unsigned long long first, unsigned int count, float* u)
{
    const unsigned int j = ggx_cuda_index();
    if (j < count) {
        ggx_uniform_pair pair = ggx_sobol_launch_pair(seed, first, j);
        u[j] = pair.u1;
        u[count + j] = pair.u2;
    }
}
