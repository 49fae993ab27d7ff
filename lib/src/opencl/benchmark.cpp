// benchmark.cpp - the programs the bench jobs build (ggxcl/benchmark.hpp).
#include "ggxcl/benchmark.hpp"

#include "device_contract.hpp"
#include "device_quirks.hpp"
#include "ggxcl/error.hpp"
#include "kernel_launch.hpp"
#include "validated_params.hpp"

namespace ggxcl::benchmark {

// Both make the launch's ProgramVariant and its options as the Sampler's launches do; the
// device's quirk options are what build_program appends.
ProgramText enqueue_program(const Sampler& sampler, const SampleParams& params, FieldSet fields)
{
    const detail::ValidatedParams valid = detail::validated(params);
    if (fields.empty())
        throw InvalidArgument("fields", "none", "at least one field (" + field_list() + ")");
    const cl::Device& device = sampler.device();
    const detail::ProgramVariant variant =
        detail::variant_of(detail::ProgramKind::bulk, *valid, detail::write_mask(fields));
    return {detail::program_file(variant.kind), "ggx_sample_bulk",
            detail::build_options(device, variant) + detail::device_quirk_options(device)};
}

ProgramText furnace_program(const Sampler& sampler, const SampleParams& params)
{
    const detail::ValidatedParams valid = detail::validated(params);
    const cl::Device& device = sampler.device();
    const detail::ProgramVariant variant =
        detail::variant_of(detail::ProgramKind::furnace, *valid, detail::write_mask({Field::weight}));
    return {detail::program_file(variant.kind), "ggx_furnace_bulk",
            detail::build_options(device, variant) + detail::device_quirk_options(device)};
}

} // namespace ggxcl::benchmark
