// bind_user_sampler.cpp - ggxcl.UserSampler: a sampler of the user's own in
// one file, passed to Sampler.sample, pdf, furnace and histogram in place of
// a method's name.
#include "python_docs.hpp"
#include "bind_user_sampler.hpp"

#include <memory>
#include <string>

#include <ggxcl/ggxcl.hpp>

namespace py = pybind11;

namespace ggxpy {

void register_user_sampler(py::module_& m)
{
    // The holder is non-const for pybind11; the object has no mutating member.
    py::class_<ggxcl::UserSampler, std::shared_ptr<ggxcl::UserSampler>>(
        m, "UserSampler", docs::UserSampler)
        .def(py::init([](const std::string& path, const py::object& name) {
                 return std::const_pointer_cast<ggxcl::UserSampler>(
                     ggxcl::UserSampler::load(path, name.is_none() ? "" : name.cast<std::string>()));
             }),
             py::arg("path"), py::arg("name") = py::none(), docs::UserSampler_init)
        .def_property_readonly("name", &ggxcl::UserSampler::name)
        .def_property_readonly("path", &ggxcl::UserSampler::path)
        .def_property_readonly("distribution",
                               [](const ggxcl::UserSampler& s) { return std::string(ggxcl::distribution_name(s.distribution())); },
                               docs::UserSampler_distribution)
        .def_property_readonly("samples_m", &ggxcl::UserSampler::samples_m)
        .def_property_readonly("key", &ggxcl::UserSampler::key)
        .def("__repr__", [](const ggxcl::UserSampler& s) { return "ggxcl.UserSampler('" + s.path() + "', name='" + s.name() + "')"; });
}

std::shared_ptr<const ggxcl::UserSampler> user_sampler_of(const py::object& method)
{
    if (!py::isinstance<ggxcl::UserSampler>(method))
        return nullptr;
    return method.cast<std::shared_ptr<ggxcl::UserSampler>>();
}

} // namespace ggxpy
