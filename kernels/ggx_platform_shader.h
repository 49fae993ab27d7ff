// ggx_platform_shader.h - ggx_platform.h's names for the two shading
// languages: GLSL 4.50 for Vulkan (glslang, shaderc) and HLSL (glslang's HLSL
// front end, which shaderc uses; DXC).  glslang defines the same macros for
// both languages, so an HLSL shader defines GGX_HLSL before it includes a
// device header (DXC's __HLSL_VERSION is read too).
//
// What differs from the C family (docs/SHADERS.md):
//   - ggx_vec3 is the language's own vec3 / float3, and ggx_uint,
//     ggx_ulong are macros (GLSL has no typedef);
//   - 64-bit integers (ggx_philox.h, ggx_sobol.h) need
//     GL_ARB_gpu_shader_int64 in GLSL, enabled here; HLSL has uint64_t;
//   - ggx_fma is HLSL's mad (glslang computes HLSL's fma(float) in double);
//   - ggx_fmin and ggx_fmax keep OpenCL's rule for NaN (the other argument),
//     which the languages' min and max leave undefined;
//   - ggx_rint rounds half to even, as OpenCL's rint.
// Shaders have no FP_CONTRACT pragma: SPIR-V leaves contraction to the
// driver unless an operation is marked NoContraction (GLSL `precise`).
#ifndef GGX_PLATFORM_SHADER_H
#define GGX_PLATFORM_SHADER_H

#define GGX_SHADER 1
#define GGX_INLINE
#define GGX_FLT_MAX 3.402823466e+38f
#define ggx_uint uint
#define ggx_ulong uint64_t
#define ggx_real float  // GGX_ARITHMETIC 32 only (ggx_platform.h)
#define GGX_UNUSED(x)
#define GGX_TYPEDEF_STRUCT(name)

#if defined(GGX_HLSL) || defined(__HLSL_VERSION)
// ---- HLSL ----------------------------------------------------------------------------------------
#define GGX_UNROLL [unroll]
#define ggx_vec3 float3
float ggx_rsqrt(float x) { return rsqrt(x); }
float ggx_rint(float x) { return round(x); }  // SPIR-V RoundEven
float ggx_fma(float a, float b, float c) { return mad(a, b, c); }
ggx_uint ggx_as_uint(float x) { return asuint(x); }
float ggx_from_bits(ggx_uint x) { return asfloat(x); }
// Conversions through an assignment: glslang's HLSL refuses (uint64_t)x and uint64_t(x).
ggx_ulong ggx_to_ulong(ggx_uint x)
{
    ggx_ulong wide = x;
    return wide;
}
ggx_uint ggx_to_uint(ggx_ulong x)
{
    ggx_uint narrow = (ggx_uint)(x & 0xffffffffu);
    return narrow;
}
#define ggx_to_float(x) ((float)(x))
#define ggx_to_int(x) ((int)(x))

#else
// ---- GLSL ----------------------------------------------------------------------------------------
#extension GL_ARB_gpu_shader_int64 : enable
#define GGX_UNROLL
#define ggx_vec3 vec3
float ggx_rsqrt(float x) { return inversesqrt(x); }
float ggx_rint(float x) { return roundEven(x); }
float ggx_fma(float a, float b, float c) { return fma(a, b, c); }
ggx_uint ggx_as_uint(float x) { return floatBitsToUint(x); }
float ggx_from_bits(ggx_uint x) { return uintBitsToFloat(x); }
#define ggx_to_ulong(x) ggx_ulong(x)
#define ggx_to_uint(x) ggx_uint(x)
#define ggx_to_float(x) float(x)
#define ggx_to_int(x) int(x)
#endif

// ---- both ----------------------------------------------------------------------------------------
float ggx_sqrt(float x) { return sqrt(x); }
float ggx_fabs(float x) { return abs(x); }
float ggx_fmin(float a, float b) { return (a < b || isnan(b)) ? a : b; }
float ggx_fmax(float a, float b) { return (a > b || isnan(b)) ? a : b; }
float ggx_copysign(float x, float y)
{
    return ggx_from_bits((ggx_as_uint(x) & 0x7fffffffu) | (ggx_as_uint(y) & 0x80000000u));
}
float ggx_clamp(float x, float lo, float hi) { return ggx_fmin(ggx_fmax(x, lo), hi); }

#endif
