// ggx_planes_shader.h - the storage buffers of the runtime's compute shaders
// that read and write planes of floats (GLSL and HLSL): `ggx_inputs` (binding
// 0, read) and `ggx_outputs` (binding 1, written).  Component c of entry j of a
// plane set at `at` is [at + c * stride + j], as in OpenCL.
#ifndef GGX_PLANES_SHADER_H
#define GGX_PLANES_SHADER_H

#if defined(GGX_HLSL) || defined(__HLSL_VERSION)
[[vk::binding(0, 0)]] StructuredBuffer<float> ggx_inputs;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> ggx_outputs;
#else
layout(std430, set = 0, binding = 0) readonly buffer ggx_inputs_block { float ggx_inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer ggx_outputs_block { float ggx_outputs[]; };
#endif

#endif
