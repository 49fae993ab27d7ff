// bind_user_sampler.hpp - ggxcl.UserSampler, and the sampler a `method`
// argument holds when it is one.
#pragma once

#include <memory>

#include <pybind11/pybind11.h>

#include <ggxcl/ggxcl.hpp>

namespace ggxpy {

void register_user_sampler(pybind11::module_& m);

// The UserSampler that `method` is, or null (a method's name).
std::shared_ptr<const ggxcl::UserSampler> user_sampler_of(const pybind11::object& method);

} // namespace ggxpy
