// kernel_launch.hpp - what the Sampler's front ends share to launch the
// kernels: build options of a request, the parameter arguments, count
// checks and the 1-D launch with a fixed work-group size.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ggxcl/sampler.hpp"
#include "program_cache.hpp"
#include "program_variant.hpp"

namespace ggxcl::detail {

constexpr std::size_t preferred_group_size = 256;

// Whether a request's alphas are all isotropic, and its views all above the horizon, with the
// caller's buffers (their promises where a buffer is set).
bool is_isotropic(const SampleParams& params, const DeviceInputs& inputs);
bool is_above_horizon(const SampleParams& params, const DeviceInputs& inputs);

// The variant of a request with the caller's per-sample buffers: the per-sample flags are the
// buffers set, the promises theirs (program_variant.hpp's variant_of without them).
ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                          const DeviceInputs& inputs);

// A variant's options on `device`: its -D options (variant_defines) and the precision mode's
// options there (precision_options, ggxcl/user_kernels.hpp).
std::string build_options(const cl::Device& device, const ProgramVariant& variant);

// Arguments first_arg.. of every kernel: the GGX_PARAM_ARG_COUNT parameter
// arguments of ggx_contract.h (the uniform floats, the per-sample view,
// alpha, normal and uniforms buffers, then their offsets).
void set_param_args(cl::Kernel& kernel, cl_uint first_arg, const SampleParams& p, const DeviceInputs& in);

void check_launch_count(std::uint64_t count, std::uint32_t stride);

// Throws InvalidArgument naming `name` when `array` (if its buffer is set)
// holds fewer than planes x stride floats after its offset.
void check_buffer_size(const DeviceArray& array, const std::string& name, int planes, std::uint64_t stride);
// The same for every buffer of a launch of `stride` (outputs and per-sample
// inputs; alpha has one plane where the program is isotropic).
void check_buffer_sizes(const DeviceOutputs* outputs, const DeviceInputs& inputs, const SampleParams& params,
                        std::uint64_t stride);

// The work-group size of a launch: `requested`, or for 0 the default within the device's maximum.
std::size_t group_size(std::size_t device_max, std::size_t requested);

// One work-item per sample: kernel `name` over the whole work-groups, then
// `name`_tail (same arguments) over the last partial one with a global
// offset; `make` leases a kernel by name with its arguments set, and only
// the kernels a count needs are leased.  Returns the event of the launch,
// or a marker on both.
using KernelMaker = std::function<KernelLease(const std::string& name)>;
cl::Event launch_split(cl::CommandQueue& queue, std::size_t group, const KernelMaker& make,
                       const std::string& name, std::uint32_t count, const std::vector<cl::Event>* wait);

} // namespace ggxcl::detail
