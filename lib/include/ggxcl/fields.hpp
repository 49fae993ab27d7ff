// fields.hpp - the per-sample outputs a caller can ask for.  Only the
// requested fields are computed and written (no pdf when nobody reads it).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace ggxcl {

// The numeric values are the kernels' field ids, GGX_FIELD_* of the device
// header ggx_contract.h (the library does not build when they differ).
enum class Field {
    m = 0,      // microfacet normal, 3 floats
    o = 1,      // reflected direction, 3 floats
    pdf_m = 2,  // density of m per steradian
    pdf_o = 3,  // density of o per steradian
    weight = 4, // f cos(o) / pdf(o) with Fresnel 1 (or a dielectric's), height-correlated G2; 0 when wasted
    u = 5,      // the uniforms (u1, u2) the sample was drawn from, 2 floats (3 with u3 for a dielectric)
};

inline constexpr std::array<Field, 6> all_fields = {Field::m,     Field::o,      Field::pdf_m,
                                                    Field::pdf_o, Field::weight, Field::u};

std::string_view field_name(Field field);   // "m", "o", "pdf_m", "pdf_o", "weight", "u"
Field parse_field(std::string_view name);   // throws InvalidArgument naming the allowed fields
int field_columns(Field field);             // 3 for m and o, 2 for u, else 1
// The same for a request: u has 3 columns (u1, u2, u3) for a dielectric (eta set).
int field_columns(Field field, bool dielectric);
std::string field_list();                   // "m, o, pdf_m, pdf_o, weight, u"

// Fields parsed from a comma-separated list such as "m,o,pdf_m", in the given order.
std::vector<Field> parse_field_list(std::string_view list);

// A set of fields as a bit mask.
class FieldSet {
public:
    FieldSet() = default;
    FieldSet(std::initializer_list<Field> fields);
    FieldSet(const std::vector<Field>& fields);
    static FieldSet all();

    FieldSet& add(Field field) { bits_ |= 1u << static_cast<unsigned>(field); return *this; }
    bool has(Field field) const { return bits_ & (1u << static_cast<unsigned>(field)); }
    bool empty() const { return bits_ == 0; }
    unsigned bits() const { return bits_; }

private:
    unsigned bits_ = 0;
};

} // namespace ggxcl
