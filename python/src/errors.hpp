// errors.hpp - ggxcl's C++ exceptions as Python exceptions: InvalidArgument
// (a ValueError with the parameter's name in .parameter), DeviceError (a
// RuntimeError) and its subclasses BuildError (with the build log in .log)
// and DeviceLost.
#pragma once

#include <pybind11/pybind11.h>

namespace ggxpy {

void register_errors(pybind11::module_& m);

} // namespace ggxpy
