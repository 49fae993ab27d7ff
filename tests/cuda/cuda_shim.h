// cuda_shim.h - what cuda_runtime.h would give a CUDA translation unit, for
// clang's CUDA compiler without the CUDA toolkit (clang++ -x cuda
// -nocudainc -nocudalib): the function space attributes, the force-inline
// keyword, the CUDA math API's float functions the ggxcl device headers
// (and the worked user sampler's intrinsics) call, and the thread indices (threadIdx, blockIdx, ...).  Device code only: each function is what
// the CUDA headers make of it on the device (an LLVM builtin).
#pragma once

#define __host__ __attribute__((host))
#define __device__ __attribute__((device))
#define __global__ __attribute__((global))
#define __forceinline__ inline __attribute__((always_inline))

__device__ inline float sqrtf(float x) { return __builtin_sqrtf(x); }
__device__ inline float fabsf(float x) { return __builtin_fabsf(x); }
__device__ inline float fminf(float a, float b) { return __builtin_fminf(a, b); }
__device__ inline float fmaxf(float a, float b) { return __builtin_fmaxf(a, b); }
__device__ inline float rintf(float x) { return __builtin_rintf(x); }
__device__ inline float copysignf(float x, float y) { return __builtin_copysignf(x, y); }
__device__ inline float fmaf(float a, float b, float c) { return __builtin_fmaf(a, b, c); }
__device__ inline float __sinf(float x) { return __nvvm_sin_approx_f(x); }
__device__ inline float __cosf(float x) { return __nvvm_cos_approx_f(x); }
__device__ inline unsigned int __float_as_uint(float x) { return __builtin_bit_cast(unsigned int, x); }

// threadIdx, blockIdx, blockDim and gridDim, from clang's own header.
#include <__clang_cuda_builtin_vars.h>
