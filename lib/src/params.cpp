// params.cpp - validation of sampling parameters; every message names the
// parameter, the bad value and what is allowed.
#include "ggxcl/params.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "ggxcl/error.hpp"

namespace ggxcl {

namespace {

std::string text(double value)
{
    std::ostringstream out;
    out.precision(9);
    out << value;
    return out.str();
}

std::string text(const Vec3& v)
{
    return text(v.x) + "," + text(v.y) + "," + text(v.z);
}

void check_alpha(const char* name, float alpha)
{
    if (!(alpha > 0.0f) || !std::isfinite(alpha))
        throw InvalidArgument(name, text(alpha), "a finite number > 0");
}

void check_direction(const char* name, const Vec3& v)
{
    bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    if (!finite || (v.x == 0.0f && v.y == 0.0f && v.z == 0.0f))
        throw InvalidArgument(name, text(v), "a finite vector of non-zero length");
}

void check_isotropic(Method method, float alpha_x, float alpha_y)
{
    if (method == Method::caps_iso && alpha_x != alpha_y)
        throw InvalidArgument("alpha", text(alpha_x) + "," + text(alpha_y),
                              "one value (alpha_x == alpha_y) for caps-iso, which is isotropic");
}

} // namespace

std::string_view precision_name(Precision precision)
{
    switch (precision) {
    case Precision::precise: return "precise";
    case Precision::fast: return "fast";
    case Precision::relaxed: return "relaxed";
    }
    return "unknown";
}

Precision parse_precision(std::string_view name)
{
    for (Precision p : {Precision::precise, Precision::fast, Precision::relaxed})
        if (precision_name(p) == name)
            return p;
    throw InvalidArgument("precision", std::string(name), "one of precise, fast, relaxed");
}

Vec3 unit_vector(const Vec3& v)
{
    double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    return {float(v.x / len), float(v.y / len), float(v.z / len)};
}

Vec3 view_from_angles(double theta_degrees, double phi_degrees)
{
    const double to_radians = 3.14159265358979323846 / 180.0;
    double t = theta_degrees * to_radians, p = phi_degrees * to_radians;
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}

void validate(const SampleParams& params)
{
    check_alpha("alpha_x", params.alpha_x);
    check_alpha("alpha_y", params.alpha_y);
    check_isotropic(params.method, params.alpha_x, params.alpha_y);
    check_direction("view", params.view);
    check_direction("normal", params.normal);
}

SampleParams normalized(const SampleParams& params)
{
    validate(params);
    SampleParams out = params;
    out.view = unit_vector(params.view);
    out.normal = unit_vector(params.normal);
    return out;
}

void validate(const SampleRange& range)
{
    if (range.count == 0)
        throw InvalidArgument("count", "0", "at least 1 sample");
    if (range.count > std::numeric_limits<std::uint64_t>::max() - range.first)
        throw InvalidArgument("count", std::to_string(range.count),
                              "at most 2^64 - first = " +
                                  std::to_string(std::numeric_limits<std::uint64_t>::max() - range.first));
}

void validate(const PerSampleInputs& inputs, const SampleParams& params, std::uint64_t count)
{
    auto check_size = [count](const char* name, std::size_t size) {
        if (size != 0 && size != count)
            throw InvalidArgument(name, std::to_string(size) + " entries",
                                  "0 (uniform) or one per sample (" + std::to_string(count) + ")");
    };
    check_size("views", inputs.views.size());
    check_size("alphas", inputs.alphas.size());
    check_size("normals", inputs.normals.size());
    for (const Vec3& v : inputs.views)
        check_direction("view", v);
    for (const Vec3& n : inputs.normals)
        check_direction("normal", n);
    for (const auto& a : inputs.alphas) {
        check_alpha("alpha_x", a[0]);
        check_alpha("alpha_y", a[1]);
        check_isotropic(params.method, a[0], a[1]);
    }
}

} // namespace ggxcl
