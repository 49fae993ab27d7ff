// program_variant.cpp - a request's program variant and its -D options.
#include "program_variant.hpp"

#include <iterator>

#include "device_contract.hpp"

namespace ggxcl::detail {

namespace {

struct ProgramKindNames {
    const char* name;
    const char* file;
};
// By ProgramKind.
constexpr ProgramKindNames kind_names[] = {
    {"bulk", "ggx_bulk.cl"}, {"furnace", "ggx_furnace.cl"}, {"histogram", "ggx_histogram.cl"}};
static_assert(std::size(kind_names) == std::size(all_program_kinds));

} // namespace

const char* program_file(ProgramKind kind)
{
    return kind_names[static_cast<int>(kind)].file;
}

const char* program_kind_name(ProgramKind kind)
{
    return kind_names[static_cast<int>(kind)].name;
}

ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask)
{
    ProgramVariant v;
    v.kind = kind;
    v.method = params.method;
    v.precision = params.precision;
    v.sequence = params.sequence;
    v.write_mask = write_mask;
    v.isotropic = method_traits(params.method).isotropic_only || params.world_space ||
                  params.alpha_x == params.alpha_y;
    v.below_horizon = !view_above_horizon(params.view, params.normal, uses_normal(params));
    v.world_space = params.world_space;
    v.guards = params.guards;
    v.normal_is_z = params.normal.x == 0.0f && params.normal.y == 0.0f && params.normal.z == 1.0f;
    v.dielectric = params.eta != 0.0f;
    v.importance = v.dielectric && params.transport == Transport::importance;
    v.user = params.user_sampler;
    return with_kind_fixed(v);
}

ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                          const PerSampleKinds& kinds)
{
    ProgramVariant v = variant_of(kind, params, write_mask);
    v.per_sample_view = kinds.view;
    v.per_sample_alpha = kinds.alpha;
    v.per_sample_normal = kinds.normal;
    v.per_sample_uniforms = kinds.uniforms;
    v.isotropic = kinds.isotropic;
    v.below_horizon = !kinds.above_horizon;
    v.normal_is_z = v.normal_is_z && !kinds.normal;
    return with_kind_fixed(v);
}

ProgramVariant variant_of_host_inputs(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                                      const PerSampleInputs& inputs)
{
    PerSampleKinds kinds;
    kinds.view = !inputs.views.empty();
    kinds.alpha = !inputs.alphas.empty();
    kinds.normal = !inputs.normals.empty();
    kinds.uniforms = !inputs.uniforms.empty();
    kinds.isotropic = method_traits(params.method).isotropic_only || params.world_space || all_isotropic(inputs, params);
    kinds.above_horizon = all_views_above_horizon(inputs, params);
    return variant_of(kind, params, write_mask, kinds);
}

std::vector<std::pair<std::string, long>> variant_define_list(const ProgramVariant& v)
{
    std::vector<std::pair<std::string, long>> list = {{"GGX_METHOD", method_id(v.method)},
                                                      {"GGX_WRITE_MASK", long(v.write_mask)},
                                                      {"GGX_SEQUENCE", sequence_id(v.sequence)}};
#define GGX_PROGRAM_FLAG_DEFINE(field, macro) list.emplace_back(macro, v.field ? 1 : 0);
    GGX_PROGRAM_FLAGS(GGX_PROGRAM_FLAG_DEFINE)
#undef GGX_PROGRAM_FLAG_DEFINE
    if (v.kind == ProgramKind::histogram) {
        list.emplace_back("GGX_BINS_Z", v.bins.bins_z);
        list.emplace_back("GGX_BINS_PHI", v.bins.bins_phi);
        list.emplace_back("GGX_BIN_M", v.bins.of_m ? 1 : 0);
    }
    return list;
}

std::string variant_defines(const ProgramVariant& v)
{
    std::string options;
    for (const auto& [name, value] : variant_define_list(v))
        options += (options.empty() ? "-D" : " -D") + name + "=" + std::to_string(value);
    if (v.method == Method::user && v.user)
        options += user_sampler_options(*v.user);
    return options;
}

ProgramVariant with_kind_fixed(ProgramVariant v)
{
    if (v.kind != ProgramKind::histogram)
        v.bins = {};
    if (v.kind != ProgramKind::bulk)
        v.eval = false;
    if (v.kind == ProgramKind::furnace)
        v.write_mask = 1u << GGX_FIELD_WEIGHT;
    if (v.kind == ProgramKind::histogram) {
        v.write_mask = 0;
        v.per_sample_view = v.per_sample_alpha = v.per_sample_normal = v.per_sample_uniforms = false;
        v.guards = true;
    }
    return v;
}

std::string variant_key(const ProgramVariant& v)
{
    return std::string(program_kind_name(v.kind)) + " " + std::string(precision_name(v.precision)) + " " +
           variant_defines(v);
}

bool variant_is_reachable(const ProgramVariant& v)
{
    const MethodTraits& traits = method_traits(v.method);
    if ((traits.isotropic_only || v.world_space) && !v.isotropic)
        return false;
    if (v.per_sample_normal && v.normal_is_z)
        return false;
    if ((v.importance && !v.dielectric) || (v.dielectric && !traits.dielectric))
        return false;
    if ((v.method == Method::user) != bool(v.user) || (v.user && (v.dielectric || v.world_space)))
        return false;
    if (v.kind == ProgramKind::histogram && (v.bins.bins_z < 1 || v.bins.bins_phi < 1))
        return false;
    return v.write_mask < (1u << GGX_FIELD_COUNT) && variant_key(with_kind_fixed(v)) == variant_key(v);
}

} // namespace ggxcl::detail
