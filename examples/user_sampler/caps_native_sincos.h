// caps_native_sincos.h - a user sampler: caps (Dupuy & Benyoub 2023,
// spherical caps) with the device's native sine and cosine in place of the
// library's accurate ones (ggx_sincos_2pi, within 0.86 ulp).  OpenCL's
// native_sin and native_cos have implementation-defined accuracy; on a GPU
// they are a hardware instruction.  Does the speed they buy cost accuracy
// that a renderer would see?  docs/USER-SAMPLERS.md has what ggxcl found.
//
//   ggx histogram --sampler examples/user_sampler/caps_native_sincos.h --check 1e-3 --out out/native
//   ggx bench --methods caps --sampler examples/user_sampler/caps_native_sincos.h --reproduces caps
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

// sin and cos of 2 pi u by the device's native functions: OpenCL's native_sin and native_cos,
// CUDA's intrinsics __sinf and __cosf (sin.approx.f32), the C library's in C++.
GGX_INLINE void native_sincos_2pi(float u, float* s, float* c)
{
#if defined(__OPENCL_C_VERSION__)
    *s = native_sin(GGX_TWO_PI * u);
    *c = native_cos(GGX_TWO_PI * u);
#elif defined(__CUDACC__) || defined(__CUDA__)  // nvcc; clang -x cuda
    *s = __sinf(GGX_TWO_PI * u);
    *c = __cosf(GGX_TWO_PI * u);
#else
    *s = sinf(GGX_TWO_PI * u);
    *c = cosf(GGX_TWO_PI * u);
#endif
}

// caps' draw (ggx_sample_caps.h), the azimuth by native_sincos_2pi.
GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    const float ti = ggx_t(i, ax, ay);
    const ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), 1.0f / ti);  // the stretched view (Heitz 2018, sec. 2)
    const float z = (1.0f - u2) * (1.0f + v.z) - v.z;                 // the cap z > -v.z (Dupuy & Benyoub eq. 10)
    const float sin_theta = ggx_sqrt(ggx_clamp(1.0f - z * z, 0.0f, 1.0f));
    float sin_phi, cos_phi;
    native_sincos_2pi(u1, &sin_phi, &cos_phi);
    const ggx_vec3 c = ggx_vec3_make(sin_theta * cos_phi, sin_theta * sin_phi, z);
    const float inv_sum = ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
    return ggx_guard(ggx_finish_vndf_sample(i, ggx_add(c, v), ax, ay, ti, inv_sum), inv_sum, ax, ay);
}

// The density is the GGX VNDF's reflection pdf, as for caps.
GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_caps(i, o, ax, ay);
}
