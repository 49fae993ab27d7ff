// request.hpp - the keyword arguments of Sampler.sample, pdf, furnace and
// histogram turned into the library's parameters: the method by name (or a
// user sampler), alpha
// as a number, a pair or a per-sample array, the view from (theta, phi)
// degrees or as a vector or per-sample array, the normal likewise, the
// precision mode, the sequence, the caller's uniforms, and a dielectric's
// relative index and transport.
#pragma once

#include <cstddef>
#include <string>

#include <pybind11/pybind11.h>

#include <ggxcl/ggxcl.hpp>

namespace ggxpy {

struct RequestArgs {
    pybind11::object method;  // a method's name or a ggxcl.UserSampler
    std::size_t count = 0;  // samples (or directions): the rows of per-sample arrays
    pybind11::object alpha, view, normal, precision, uniforms;
    double theta = 60.0, phi = 0.0;
    std::string sequence = "philox";
    bool world_space = false;
    pybind11::object eta = pybind11::none();  // None: a conductor (Fresnel 1)
    std::string transport = "radiance";
};

struct Request {
    ggxcl::SampleParams params;
    ggxcl::PerSampleInputs per_sample;
};

// The keyword arguments as the bindings receive them.
RequestArgs args_of(const pybind11::object& method, const pybind11::object& n, const pybind11::object& alpha, double theta, double phi,
                    const pybind11::object& view, const pybind11::object& normal, const pybind11::object& precision,
                    const std::string& sequence, const pybind11::object& uniforms, bool world_space);

// `args` for a rough dielectric of index `eta` (None: none) in `transport`.
RequestArgs with_dielectric(RequestArgs args, const pybind11::object& eta, const std::string& transport);

// Throws ggxcl::InvalidArgument naming the argument at fault.
Request make_request(const RequestArgs& args);

} // namespace ggxpy
