// c_params.hpp - the C API's structs as the C++ API's: parameters (every
// enum value checked, naming the field of ggxcl_params), ranges, field
// masks and the outputs' members by field.
#pragma once

#include "ggxcl/ggxcl.h"
#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::capi {

SampleParams to_params(const ggxcl_params* params);
Precision to_precision(int id, const char* parameter);  // InvalidArgument naming `parameter` for an unknown id
Field to_field(int id, const char* parameter);          // the same
SampleRange to_range(const ggxcl_range* range);
FieldSet to_fields(unsigned mask);  // InvalidArgument naming "fields" for bits beyond the fields

// The member of an outputs struct (ggxcl_device_outputs, ggxcl_host_outputs) that holds `field`.
template <class Outputs>
auto& output_of(Outputs& outputs, Field field)
{
    switch (field) {
    case Field::m: return outputs.m;
    case Field::o: return outputs.o;
    case Field::pdf_m: return outputs.pdf_m;
    case Field::pdf_o: return outputs.pdf_o;
    case Field::weight: return outputs.weight;
    case Field::u: break;
    }
    return outputs.u;
}

} // namespace ggxcl::capi
