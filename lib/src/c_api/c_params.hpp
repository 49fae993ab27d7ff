// c_params.hpp - the C API's structs as the C++ API's: parameters (every
// enum value checked, naming the field of ggxcl_params), ranges and the
// field masks.
#pragma once

#include "ggxcl/ggxcl.h"
#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::capi {

SampleParams to_params(const ggxcl_params* params);
Precision to_precision(int id, const char* parameter);  // InvalidArgument naming `parameter` for an unknown id
SampleRange to_range(const ggxcl_range* range);
FieldSet to_fields(unsigned mask);  // InvalidArgument naming "fields" for bits beyond the fields

} // namespace ggxcl::capi
