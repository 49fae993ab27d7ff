// bind_pyopencl.hpp - ggxcl in a pyopencl pipeline: a Sampler on a
// pyopencl context and device, and Sampler.enqueue writing into pyopencl
// Buffers on a pyopencl queue, returning a pyopencl Event; the handles pass
// by their int_ptr, each side keeping its own reference.
#pragma once

#include <memory>

#include <pybind11/pybind11.h>

#include <ggxcl/ggxcl.hpp>

namespace ggxpy {

// A Sampler on the OpenCL context and device of pyopencl's objects.
std::unique_ptr<ggxcl::Sampler> sampler_on(const pybind11::object& context, const pybind11::object& device);

// Adds Sampler.enqueue to the bound class (InvalidArgument naming the API on a Vulkan sampler).
void add_enqueue(pybind11::class_<ggxcl::Backend>& sampler);

} // namespace ggxpy
