// chunk_inputs.hpp - the caller's per-sample inputs in host memory as the
// device buffers an OpenCL launch reads (planes of stride `capacity`), with
// the promises they keep: made once, refilled chunk by chunk.
#pragma once

#include "device_faults.hpp"
#include "planar_inputs.hpp"
#include "queue_waits.hpp"
#include "ggxcl/sampler.hpp"

namespace ggxcl::detail {

// Device buffers for the per-sample inputs of `capacity` samples, refilled per chunk by upload().
struct ChunkInputs {
    DeviceInputs buffers;

    ChunkInputs(const cl::Context& context, const PerSampleInputs& in, const SampleParams& params,
                std::uint64_t capacity)
    {
        buffers.views_above_horizon = all_views_above_horizon(in, params);
        buffers.isotropic = all_isotropic(in, params);
        auto make = [&](int planes) {
            return device_buffer(context, CL_MEM_READ_ONLY, planes * capacity * sizeof(float));
        };
        if (!in.views.empty()) buffers.view = make(3);
        if (!in.alphas.empty()) buffers.alpha = make(2);
        if (!in.normals.empty()) buffers.normal = make(3);
        if (!in.uniforms.empty()) buffers.uniforms = make(in.lobe_uniforms.empty() ? 2 : 3);
    }

    void upload(cl::CommandQueue& queue, const PerSampleInputs& in, std::uint64_t start, std::uint64_t n,
                std::uint64_t capacity)
    {
        if (!in.views.empty()) write(queue, buffers.view, planar_units(in.views, start, n, capacity));
        if (!in.alphas.empty()) write(queue, buffers.alpha, planar_pairs(in.alphas, start, n, capacity));
        if (!in.normals.empty()) write(queue, buffers.normal, planar_units(in.normals, start, n, capacity));
        if (!in.uniforms.empty()) write(queue, buffers.uniforms, planar_uniforms(in, start, n, capacity));
    }

    static void write(cl::CommandQueue& queue, cl::Buffer& buffer, const std::vector<float>& data)
    {
        write_and_wait(queue, buffer, 0, data.size() * sizeof(float), data.data());
    }
};

} // namespace ggxcl::detail
