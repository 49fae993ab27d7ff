// module.cpp - the compiled part of the ggxcl Python package (ggxcl._ggxcl);
// ggxcl/__init__.py re-exports it with the documentation.
#include <pybind11/pybind11.h>

#include <ggxcl/ggxcl.hpp>

#include "bind_sampler.hpp"
#include "bind_user_sampler.hpp"
#include "errors.hpp"

PYBIND11_MODULE(_ggxcl, m)
{
    m.doc() = "GGX microfacet importance samplers on OpenCL devices (ggxcl)";
    m.attr("__version__") = std::string(ggxcl::version());
    m.attr("methods") = [] {
        pybind11::list names;
        for (ggxcl::Method method : ggxcl::all_methods)
            names.append(std::string(ggxcl::method_name(method)));
        return pybind11::tuple(names);
    }();
    m.attr("method_traits") = [] {
        pybind11::dict table;
        for (const ggxcl::MethodTraits& t : ggxcl::method_table) {
            pybind11::dict row;
            row["paper"] = std::string(t.paper);
            row["how"] = std::string(t.how);
            row["space"] = std::string(ggxcl::space_name(t.space));
            row["isotropic_only"] = t.isotropic_only;
            row["normals"] = std::string(ggxcl::distribution_name(t.normals));
            row["dielectric"] = t.dielectric;
            row["views_below"] = t.views_below;
            row["limits"] = std::string(t.limits);
            table[pybind11::str(std::string(t.name))] = row;
        }
        return table;
    }();
    ggxpy::register_errors(m);
    ggxpy::register_user_sampler(m);
    ggxpy::register_sampler(m);
}
