// reference_bridge.cpp - library types to reference types and back.
#include "reference_bridge.hpp"

#include "ggx_quadrature.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace ggxbridge {

namespace {

static_assert(ggxref::all_methods.size() == ggxcl::all_methods.size(), "the same methods on both sides");

using MethodPair = std::pair<ggxcl::Method, ggxref::Method>;

// Each library method with the reference method of the same name, in the library's order.
const std::array<MethodPair, ggxcl::all_methods.size()>& method_pairs()
{
    static const auto pairs = [] {
        std::array<MethodPair, ggxcl::all_methods.size()> out{};
        for (std::size_t k = 0; k < out.size(); ++k) {
            const ggxcl::Method m = ggxcl::all_methods[k];
            bool found = false;
            for (ggxref::Method r : ggxref::all_methods)
                if (ggxcl::method_name(m) == ggxref::method_name(r))
                    out[k] = {m, r}, found = true;
            if (!found)
                throw std::logic_error("no reference method named " + std::string(ggxcl::method_name(m)));
        }
        return out;
    }();
    return pairs;
}

} // namespace

ggxref::Method reference_method(ggxcl::Method method)
{
    for (const MethodPair& p : method_pairs())
        if (p.first == method)
            return p.second;
    throw std::logic_error("not a library method: " + std::to_string(int(method)));
}

ggxcl::Method library_method(ggxref::Method method)
{
    for (const MethodPair& p : method_pairs())
        if (p.second == method)
            return p.first;
    throw std::logic_error("not a reference method: " + std::to_string(int(method)));
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
