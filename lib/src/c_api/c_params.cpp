// c_params.cpp - ggxcl_params, ggxcl_range and field masks as SampleParams,
// SampleRange and FieldSet; the C enums checked against the C++ ones.
#include "c_api/c_params.hpp"

#include <string>

#include "c_api/c_handles.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl::capi {
namespace {

#define GGXCL_C_METHOD_MATCHES(ID, identifier, name) \
    static_assert(static_cast<int>(Method::identifier) == GGXCL_METHOD_##ID);
GGX_METHOD_LIST(GGXCL_C_METHOD_MATCHES)
#undef GGXCL_C_METHOD_MATCHES
static_assert(static_cast<int>(Method::user) == GGXCL_METHOD_USER);
static_assert(GGXCL_METHOD_COUNT == all_methods.size());
static_assert(static_cast<int>(Field::m) == GGXCL_FIELD_M && static_cast<int>(Field::o) == GGXCL_FIELD_O &&
              static_cast<int>(Field::pdf_m) == GGXCL_FIELD_PDF_M && static_cast<int>(Field::pdf_o) == GGXCL_FIELD_PDF_O &&
              static_cast<int>(Field::weight) == GGXCL_FIELD_WEIGHT && static_cast<int>(Field::u) == GGXCL_FIELD_U);
static_assert(GGXCL_FIELD_COUNT == all_fields.size());
static_assert(static_cast<int>(Precision::precise) == GGXCL_PRECISION_PRECISE &&
              static_cast<int>(Precision::relaxed) == GGXCL_PRECISION_RELAXED);
static_assert(static_cast<int>(Sequence::philox) == GGXCL_SEQUENCE_PHILOX &&
              static_cast<int>(Sequence::sobol) == GGXCL_SEQUENCE_SOBOL);
static_assert(static_cast<int>(Transport::radiance) == GGXCL_TRANSPORT_RADIANCE &&
              static_cast<int>(Transport::importance) == GGXCL_TRANSPORT_IMPORTANCE);

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

// all_precisions, all_sequences, all_transports are in id order.
template <class Enum, std::size_t count>
Enum to_enum(int id, const std::array<Enum, count>& all, const char* parameter, const std::string& names)
{
    if (id < 0 || static_cast<std::size_t>(id) >= count)
        throw InvalidArgument(parameter, std::to_string(id), "0 .. " + std::to_string(count - 1) + " (" + names + ")");
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
    p.sequence = to_enum(in.sequence, all_sequences, "params.sequence", "philox, sobol");
    p.world_space = in.world_space != 0;
    p.eta = in.eta;
    p.transport = to_enum(in.transport, all_transports, "params.transport", "radiance, importance");
    if (in.user_sampler)
        p.user_sampler = in.user_sampler->sampler;
    return p;
}

Precision to_precision(int id, const char* parameter)
{
    return to_enum(id, all_precisions, parameter, precision_list());
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
