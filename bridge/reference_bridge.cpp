// reference_bridge.cpp - library types to reference types.
#include "reference_bridge.hpp"

#include <stdexcept>
#include <string>

namespace ggxapp {

ggxref::Method reference_method(ggxcl::Method m)
{
    for (ggxref::Method r : ggxref::all_methods)
        if (ggxcl::method_name(m) == ggxref::method_name(r))
            return r;
    throw std::logic_error("no reference method named " + std::string(ggxcl::method_name(m)));
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

} // namespace ggxapp
