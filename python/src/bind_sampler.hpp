// bind_sampler.hpp - ggxcl.Sampler and ggxcl.devices(): samples, pdfs, the
// fused furnace estimator and device histograms as NumPy arrays.
#pragma once

#include <pybind11/pybind11.h>

namespace ggxpy {

void register_sampler(pybind11::module_& m);

} // namespace ggxpy
