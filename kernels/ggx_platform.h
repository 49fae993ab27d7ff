// ggx_platform.h - the few language constructs the device math uses, for
// three languages: OpenCL C (the kernels), C++17 (a CPU renderer, a baker,
// the native baseline, the host tests) and CUDA (nvcc, or clang -x cuda),
// and for GLSL and HLSL (ggx_platform_shader.h).
// The device headers call these names and never the bare math functions,
// so float math stays float in every language: in C++ an unqualified
// sqrt(float) may be the double function.
//
//   ggx_uint, ggx_ulong    32- and 64-bit unsigned integers
//   GGX_INLINE             a function inlined into its caller (__host__ __device__ in CUDA)
//   GGX_UNROLL             unroll the loop that follows
//   GGX_FLT_MAX            the largest finite float
//   ggx_sqrt, ggx_rsqrt, ggx_fabs, ggx_fmin, ggx_fmax, ggx_rint, ggx_copysign,
//   ggx_fma, ggx_clamp     float functions with OpenCL C's meaning
//   GGX_FMA                a fused multiply-add where the hardware has one
//   ggx_as_uint            the bits of a float
//   ggx_to_float, ggx_to_int, ggx_to_uint, ggx_to_ulong
//                          conversions (shading languages have no C casts)
//   GGX_UNUSED(x)          a parameter a function form does not read
//   GGX_TYPEDEF_STRUCT(n)  after `struct n { ... };`, the name n alone names the type
//   GGX_SHADER             1 in GLSL and HLSL, 0 in the C family
//   ggx_real, GGX_R(x)     the arithmetic type of the device math and a literal of it
//                          (GGX_ARITHMETIC, below)
//
// In OpenCL C they are the built-ins themselves, so the kernels compile to
// what they did before these names existed.  The accuracy differs by
// language: OpenCL allows 3 ulp for sqrt and 2.5 ulp for division unless
// built with -cl-fp32-correctly-rounded-divide-sqrt; C++ and CUDA round
// both correctly (CUDA with its default -prec-sqrt=true -prec-div=true).
// ggx_fma is one rounding everywhere, and in OpenCL C the only fused
// multiply-add (FP_CONTRACT is off); where C++ targets a CPU without
// hardware fma (libm would emulate it, slowly) GGX_NO_FMA defaults to 1 and
// ggx_sincos.h uses a multiply and an add instead.
#ifndef GGX_PLATFORM_H
#define GGX_PLATFORM_H

// GGX_ARITHMETIC: the arithmetic type of the device math, ggx_real: 32 (float, the default) or 16
// (half precision; so far C++'s _Float16 only, for the headers written on ggx_real: the math, the
// samplers, the dielectric, the sincos; Philox, Sobol and the kernels' I/O stay float).  GGX_R(x)
// makes the float literal x (0.5f) a ggx_real: in float the literal itself; in half a conversion that
// the compiler folds, so that no operation is promoted to float by a literal.
// One arithmetic per translation unit: in C++ a half build includes the headers inside a namespace
// of its own, after <cmath>, <cstdint> and <cstring> (tests/host/test_half_math.cpp).
#ifndef GGX_ARITHMETIC
#define GGX_ARITHMETIC 32
#endif
#if GGX_ARITHMETIC != 32 && GGX_ARITHMETIC != 16
#error "GGX_ARITHMETIC: 32 (float) or 16 (half)"
#endif
#if GGX_ARITHMETIC == 16 && !defined(__cplusplus)
#error "GGX_ARITHMETIC 16: the device headers compute in half precision in C++ (_Float16) only so far"
#endif

#if defined(__OPENCL_C_VERSION__)
// ---- OpenCL C ------------------------------------------------------------
// No contraction: OpenCL C lets a compiler fuse a * b + c into one fma where
// it likes, and compilers decide differently per program (NVIDIA's did for
// two programs with the same math), so the same sample would get other bits
// in another program.  Off from here to the end of the program, the
// including kernel's own code too; ggx_fma fuses where the math wants it.
// Built with -cl-fast-relaxed-math (relaxed mode) the program may contract.
#if !defined(__FAST_RELAXED_MATH__)
#pragma OPENCL FP_CONTRACT OFF
#endif
typedef uint ggx_uint;
typedef ulong ggx_ulong;
typedef float ggx_real;
// static: a plain `inline` function left uninlined (an unoptimized build, SPIR-V) has no external
// definition, and llvm-spirv marks its body for import, which spirv-val rejects.
#define GGX_INLINE static inline __attribute__((always_inline))
#define GGX_UNROLL _Pragma("unroll")
#define GGX_FLT_MAX FLT_MAX
#define ggx_sqrt sqrt
#define ggx_rsqrt rsqrt
#define ggx_fabs fabs
#define ggx_fmin fmin
#define ggx_fmax fmax
#define ggx_rint rint
#define ggx_copysign copysign
#define ggx_fma fma
#define ggx_clamp clamp
#define ggx_as_uint as_uint

#elif defined(__CUDACC__) || defined(__CUDA__)  // nvcc; clang -x cuda
// ---- CUDA: the CUDA math API's float functions (cuda_runtime.h, which nvcc
// includes; a clang build without the CUDA headers declares them itself) ----
#include <string.h>
typedef unsigned int ggx_uint;
typedef unsigned long long ggx_ulong;
#if GGX_ARITHMETIC == 16
#error "GGX_ARITHMETIC 16: not yet in CUDA"
#endif
typedef float ggx_real;
#define GGX_INLINE __host__ __device__ __forceinline__
#if defined(__CUDA_ARCH__) || defined(__clang__)
#define GGX_UNROLL _Pragma("unroll")
#else
#define GGX_UNROLL  // nvcc's host pass: neither its front end nor the host compiler takes both pragmas
#endif
#define GGX_FLT_MAX 3.402823466e+38f
GGX_INLINE float ggx_sqrt(float x) { return sqrtf(x); }
GGX_INLINE float ggx_rsqrt(float x) { return 1.0f / sqrtf(x); }
GGX_INLINE float ggx_fabs(float x) { return fabsf(x); }
GGX_INLINE float ggx_fmin(float a, float b) { return fminf(a, b); }
GGX_INLINE float ggx_fmax(float a, float b) { return fmaxf(a, b); }
GGX_INLINE float ggx_rint(float x) { return rintf(x); }
GGX_INLINE float ggx_copysign(float x, float y) { return copysignf(x, y); }
GGX_INLINE float ggx_fma(float a, float b, float c) { return fmaf(a, b, c); }
GGX_INLINE ggx_uint ggx_as_uint(float x)
{
#if defined(__CUDA_ARCH__)
    return __float_as_uint(x);
#else
    ggx_uint bits;
    memcpy(&bits, &x, sizeof bits);
    return bits;
#endif
}

#elif defined(__cplusplus)
// ---- C++17 on the host -----------------------------------------------------
#include <cmath>
#include <cstdint>
#include <cstring>
typedef std::uint32_t ggx_uint;
typedef std::uint64_t ggx_ulong;
#if GGX_ARITHMETIC == 16
typedef _Float16 ggx_real;  // g++ 12 and clang 15 on x86-64; -mf16c converts in one instruction
#else
typedef float ggx_real;
#endif
#if defined(_MSC_VER)
#define GGX_INLINE __forceinline
#define GGX_UNROLL
#elif defined(__clang__)
#define GGX_INLINE inline __attribute__((always_inline))
#define GGX_UNROLL _Pragma("unroll")
#else
#define GGX_INLINE inline __attribute__((always_inline))
#define GGX_UNROLL _Pragma("GCC unroll 16")
#endif
#define GGX_FLT_MAX 3.402823466e+38f
#if !defined(GGX_NO_FMA) && !defined(__FP_FAST_FMAF) && !defined(FP_FAST_FMAF)
#define GGX_NO_FMA 1  // no hardware fma on the target: a multiply and an add (ggx_sincos.h)
#endif
// In half the functions compute in float and round once: for sqrt that is the correctly rounded
// half result (float has more than 2 x 11 + 2 bits), for fma in double; std::sqrt and std::fma are
// ambiguous on _Float16.  In float the casts do nothing.
GGX_INLINE ggx_real ggx_sqrt(ggx_real x) { return (ggx_real)std::sqrt((float)x); }
GGX_INLINE ggx_real ggx_rsqrt(ggx_real x) { return (ggx_real)(1.0f / std::sqrt((float)x)); }
GGX_INLINE ggx_real ggx_fabs(ggx_real x) { return (ggx_real)std::fabs((float)x); }
// fmin and fmax by a compare and a select, with their rule for NaN (the other
// argument): x86 has no instruction with that rule, and GCC calls libm's
// fminf and fmaxf instead, out of line, which also stops the vectorizer.
GGX_INLINE ggx_real ggx_fmin(ggx_real a, ggx_real b) { return (a < b || b != b) ? a : b; }
GGX_INLINE ggx_real ggx_fmax(ggx_real a, ggx_real b) { return (a > b || b != b) ? a : b; }
GGX_INLINE ggx_real ggx_rint(ggx_real x) { return (ggx_real)std::rint((float)x); }
GGX_INLINE ggx_real ggx_copysign(ggx_real x, ggx_real y) { return (ggx_real)std::copysign((float)x, (float)y); }
#if GGX_ARITHMETIC == 16
GGX_INLINE ggx_real ggx_fma(ggx_real a, ggx_real b, ggx_real c)
{
    return (ggx_real)std::fma((double)a, (double)b, (double)c);
}
#else
GGX_INLINE float ggx_fma(float a, float b, float c) { return std::fma(a, b, c); }
#endif
GGX_INLINE ggx_uint ggx_as_uint(float x)
{
    ggx_uint bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}

#elif defined(GGX_HLSL) || defined(__HLSL_VERSION) || defined(GL_core_profile) || defined(GL_ES) || defined(VULKAN)
#include "ggx_platform_shader.h"

#else
#error "ggx_platform.h: compile the ggxcl device headers as OpenCL C, C++ (C++17), CUDA, GLSL or HLSL (-DGGX_HLSL)"
#endif

#if !defined(GGX_SHADER)
// ---- the C family: OpenCL C, C++, CUDA -------------------------------------
#define GGX_SHADER 0
#define ggx_to_float(x) ((float)(x))
#define ggx_to_int(x) ((int)(x))
#define ggx_to_uint(x) ((ggx_uint)(x))
#define ggx_to_ulong(x) ((ggx_ulong)(x))
#define GGX_UNUSED(x) (void)(x)
#define GGX_TYPEDEF_STRUCT(name) typedef struct name name;
#endif

// GGX_FMA(a, b, c): a * b + c fused (ggx_fma) where the device has hardware
// fma, a multiply and an add where GGX_NO_FMA is 1 (C++ without fma, above;
// OpenCL devices without it, set by the runtime: a software fma is slow).
// Either way the same on every program of one device.
#ifndef GGX_NO_FMA
#define GGX_NO_FMA 0
#endif
#if GGX_NO_FMA
#define GGX_FMA(a, b, c) ((a) * (b) + (c))
#else
#define GGX_FMA(a, b, c) ggx_fma((a), (b), (c))
#endif

// fmin(fmax(x, lo), hi), OpenCL C's clamp.
#if !defined(__OPENCL_C_VERSION__) && !GGX_SHADER
GGX_INLINE ggx_real ggx_clamp(ggx_real x, ggx_real lo, ggx_real hi) { return ggx_fmin(ggx_fmax(x, lo), hi); }
#endif

#if GGX_ARITHMETIC == 16
#define GGX_R(x) ((ggx_real)(x))
#else
#define GGX_R(x) (x)
#endif

// A uniform u in [0, 1), made in float (ggx_philox.h, ggx_sobol.h), as the ggx_real a sampler takes:
// in half rounded toward zero, so that it stays below 1 (to nearest, every u from 1 - 2^-12 on would
// round to 1.0, the edge of the disk or cap, where m lies in the surface).
#if GGX_ARITHMETIC == 16
GGX_INLINE ggx_real ggx_uniform_real(float u)
{
    ggx_real h = (ggx_real)u;
    if ((float)h > u) {  // rounded up: the next half below (u >= 0, so h > 0 and its bits step down)
        std::uint16_t bits;
        std::memcpy(&bits, &h, sizeof bits);
        bits = std::uint16_t(bits - 1u);
        std::memcpy(&h, &bits, sizeof bits);
    }
    return h;
}
#else
GGX_INLINE ggx_real ggx_uniform_real(float u) { return u; }
#endif

#endif
