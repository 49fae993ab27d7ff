// c_params.cpp - ggxcl_params, ggxcl_range and field masks as SampleParams,
// SampleRange and FieldSet, every enum value checked.
#include "c_api/c_params.hpp"

#include <string>

#include "c_api/c_handles.hpp"
#include "device_contract.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl::capi {
namespace {

// The C enums are the contract's ids (ggxcl.h), and the C++ enums are checked against the same
// ids (device_contract.hpp): the two APIs agree.  Methods come from the one list on both sides.
static_assert(GGXCL_METHOD_COUNT == all_methods.size());
static_assert(static_cast<int>(Method::user) == GGXCL_METHOD_USER);

Method to_method(int id)
{
    if (id == GGXCL_METHOD_USER)
        return Method::user;
    if (id < 0 || id >= GGXCL_METHOD_COUNT)
        throw InvalidArgument("params.method", std::to_string(id),
                              "0 .. " + std::to_string(GGXCL_METHOD_COUNT - 1) + " (" + method_list() + ") or " +
                                  std::to_string(GGXCL_METHOD_USER) + " (GGXCL_METHOD_USER)");
    return all_methods[static_cast<std::size_t>(id)];
}

// all_precisions, all_sequences, all_transports are in id order; `name` gives each one's name.
template <class Enum, std::size_t count, class Name>
Enum to_enum(int id, const std::array<Enum, count>& all, const char* parameter, Name name)
{
    if (id < 0 || static_cast<std::size_t>(id) >= count) {
        std::string names;
        for (Enum value : all)
            names += (names.empty() ? "" : ", ") + std::string(name(value));
        throw InvalidArgument(parameter, std::to_string(id), "0 .. " + std::to_string(count - 1) + " (" + names + ")");
    }
    return all[static_cast<std::size_t>(id)];
}

Vec3 to_vec3(const float (&v)[3]) { return {v[0], v[1], v[2]}; }

} // namespace

SampleParams to_params(const ggxcl_params* c)
{
    const ggxcl_params& in = require(c, "params");
    SampleParams p;
    p.method = to_method(in.method);
    p.alpha_x = in.alpha_x;
    p.alpha_y = in.alpha_y;
    p.view = to_vec3(in.view);
    p.normal = to_vec3(in.normal);
    p.precision = to_precision(in.precision, "params.precision");
    p.sequence = to_enum(in.sequence, all_sequences, "params.sequence", sequence_name);
    p.world_space = in.world_space != 0;
    p.eta = in.eta;
    p.transport = to_enum(in.transport, all_transports, "params.transport", transport_name);
    if (in.user_sampler)
        p.user_sampler = in.user_sampler->sampler;
    return p;
}

Precision to_precision(int id, const char* parameter)
{
    return to_enum(id, all_precisions, parameter, precision_name);
}

Field to_field(int id, const char* parameter)
{
    return to_enum(id, all_fields, parameter, field_name);
}

SampleRange to_range(const ggxcl_range* c)
{
    const ggxcl_range& in = require(c, "range");
    return {in.seed, in.first, in.count};
}

FieldSet to_fields(unsigned mask)
{
    const unsigned all = (1u << GGXCL_FIELD_COUNT) - 1;
    if (mask & ~all)
        throw InvalidArgument("fields", std::to_string(mask),
                              "a mask of GGXCL_FIELD_BIT(field) within " + std::to_string(all));
    FieldSet fields;
    for (Field field : all_fields)
        if (mask & GGXCL_FIELD_BIT(field))
            fields.add(field);
    return fields;
}

} // namespace ggxcl::capi

extern "C" void ggxcl_default_params(ggxcl_params* params)
{
    if (!params)
        return;
    const ggxcl::SampleParams p;
    *params = ggxcl_params{};
    params->method = static_cast<ggxcl_method>(p.method);
    params->alpha_x = p.alpha_x;
    params->alpha_y = p.alpha_y;
    params->view[0] = p.view.x, params->view[1] = p.view.y, params->view[2] = p.view.z;
    params->normal[0] = p.normal.x, params->normal[1] = p.normal.y, params->normal[2] = p.normal.z;
    params->precision = static_cast<ggxcl_precision>(p.precision);
    params->sequence = static_cast<ggxcl_sequence>(p.sequence);
    params->world_space = p.world_space ? 1 : 0;
    params->eta = p.eta;
    params->transport = static_cast<ggxcl_transport>(p.transport);
    params->user_sampler = nullptr;
}
