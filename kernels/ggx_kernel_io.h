// ggx_kernel_io.h - what only OpenCL kernels use: `restrict` on their
// buffers and the planar loads and stores of three-component values.  The
// device math (ggx_samplers.h and what it includes) needs none of it and
// compiles as C++ and CUDA too; this header is OpenCL C alone.
#ifndef GGX_KERNEL_IO_H
#define GGX_KERNEL_IO_H

#include "ggx_common.h"

// `restrict` on the bulk kernels' buffers, dropped with -DGGX_NO_RESTRICT=1:
// the runtime sets it for devices whose compiler cannot take restrict on
// inlined functions (Oclgrind).
#ifndef GGX_NO_RESTRICT
#define GGX_NO_RESTRICT 0
#endif
#if GGX_NO_RESTRICT
#define GGX_RESTRICT
#else
#define GGX_RESTRICT restrict
#endif

// Component c of value j at p[j + c * stride].
GGX_INLINE ggx_vec3 ggx_load3(__global const float* p, uint j, uint stride)
{
    return ggx_vec3_make(p[j], p[j + stride], p[j + 2u * stride]);
}

GGX_INLINE void ggx_store3(__global float* p, uint j, uint stride, ggx_vec3 v)
{
    p[j] = v.x;
    p[j + stride] = v.y;
    p[j + 2u * stride] = v.z;
}

#endif
