// reference_bridge.cpp - library types to reference types and back.
#include "reference_bridge.hpp"

#include "ggx_quadrature.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace ggxbridge {

namespace {

static_assert(ggxref::all_methods.size() == ggxcl::all_methods.size(), "the same methods on both sides");

// Both enums are made from the one list of methods (GGX_METHOD_LIST) with its ids, so a
// method's id maps it.
std::size_t method_index(int id)
{
    if (id < 0 || std::size_t(id) >= ggxcl::all_methods.size())
        throw std::logic_error("not a method id: " + std::to_string(id));
    return std::size_t(id);
}

} // namespace

ggxref::Method reference_method(ggxcl::Method method)
{
    return ggxref::all_methods[method_index(static_cast<int>(method))];
}

ggxcl::Method library_method(ggxref::Method method)
{
    return ggxcl::all_methods[method_index(static_cast<int>(method))];
}

ggxref::Params reference_params(const ggxcl::SampleParams& p)
{
    ggxref::Params r;
    r.ax = p.alpha_x;
    r.ay = p.alpha_y;
    r.i = {p.view.x, p.view.y, p.view.z};
    r.n = {p.normal.x, p.normal.y, p.normal.z};
    return r;
}

ggxcl::SampleParams library_params(ggxref::Method method, const ggxref::Params& p, ggxcl::Precision precision)
{
    ggxcl::SampleParams out;
    out.precision = precision;
    out.method = library_method(method);
    out.alpha_x = float(p.ax);
    out.alpha_y = float(p.ay);
    out.view = {float(p.i.x), float(p.i.y), float(p.i.z)};
    out.normal = {float(p.n.x), float(p.n.y), float(p.n.z)};
    return out;
}

std::vector<double> bin_probabilities(ggxcl::Method method, const ggxcl::SampleParams& params, int bins_z,
                                      int bins_phi, ggxcl::Field direction)
{
    const ggxref::Method m = reference_method(method);
    const ggxref::Params p = reference_params(params);
    return direction == ggxcl::Field::m ? ggxref::bin_probabilities_m(m, p, bins_z, bins_phi)
                                        : ggxref::bin_probabilities(m, p, bins_z, bins_phi);
}

} // namespace ggxbridge
