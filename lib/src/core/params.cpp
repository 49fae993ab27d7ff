// params.cpp - validation of sampling parameters; every message names the
// parameter, the bad value and what is allowed.  Also the validated form
// the Sampler's internal paths take (validated_params.hpp).
#include "ggxcl/params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <charconv>

#include "ggxcl/error.hpp"
#include "named_values.hpp"
#include "validated_params.hpp"

namespace ggxcl {

namespace {

// The shortest text that reads back as `value` (std::to_chars): what a user
// typed for it, in most cases ("1e-35", "0.3", "200"), not its rounding.
template <class Number>
std::string text(Number value)
{
    char digits[64];
    const std::to_chars_result end = std::to_chars(digits, digits + sizeof digits, value);
    return std::string(digits, end.ptr);
}

std::string text(const Vec3& v)
{
    return text(v.x) + "," + text(v.y) + "," + text(v.z);
}

void check_alpha(const char* name, float alpha)
{
    if (!(alpha >= min_alpha && alpha <= max_alpha))  // NaN fails the compares
        throw InvalidArgument(name, text(alpha), alpha_range);
}

void check_angle(const char* name, double degrees, double low, double high)
{
    if (!(degrees >= low && degrees <= high))
        throw InvalidArgument(name, text(degrees), "degrees from " + text(low) + " to " + text(high));
}

void check_direction(const char* name, const Vec3& v)
{
    bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    if (!finite || (v.x == 0.0f && v.y == 0.0f && v.z == 0.0f))
        throw InvalidArgument(name, text(v), "a finite vector of non-zero length");
}

// A sampler of visible normals (or of a density of its own built on them, bounded) has nothing to
// sample from a view opposite the normal: no microfacet (m.z > 0) is visible from there.  The rule
// is the samplers' domain (kernels/ggx_guards.h): iz + t(i), twice the visible area, above 1e-20,
// computed here in double without cancellation.  ndf, and a user sampler claiming the NDF, keep
// that view.
void check_view_visible(const SampleParams& params)
{
    const Distribution normals = params.method == Method::user && params.user_sampler
                                     ? params.user_sampler->distribution()
                                     : method_traits(params.method).normals;
    if (normals == Distribution::ndf)
        return;
    const bool about_normal = params.world_space || params.method == Method::caps_iso;
    const Vec3 v = params.view, n = about_normal ? params.normal : Vec3{0.0f, 0.0f, 1.0f};
    const double lv = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    const double ln = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
    const double iz = (double(v.x) * n.x + double(v.y) * n.y + double(v.z) * n.z) / (lv * ln);
    double slopes;  // ax^2 ix^2 + ay^2 iy^2 in the normal's frame
    if (about_normal) {
        const double c[3] = {double(v.y) * n.z - double(v.z) * n.y, double(v.z) * n.x - double(v.x) * n.z,
                             double(v.x) * n.y - double(v.y) * n.x};
        slopes = double(params.alpha_x) * params.alpha_x * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / (lv * lv * ln * ln);
    } else {
        const double ix = v.x / lv, iy = v.y / lv;
        slopes = double(params.alpha_x) * params.alpha_x * ix * ix + double(params.alpha_y) * params.alpha_y * iy * iy;
    }
    const double t = std::sqrt(slopes + iz * iz);
    const double twice_area = iz >= 0.0 ? iz + t : slopes / (t - iz);
    if (!(twice_area > 1e-20))
        throw InvalidArgument("view", text(v),
                              "a view from which some microfacet is visible, not opposite the normal (theta < 180 "
                              "degrees): " + sampler_name(params) + " samples visible normals (ndf takes this view)");
}

void check_isotropic(const SampleParams& params, float alpha_x, float alpha_y)
{
    if (alpha_x == alpha_y)
        return;
    const MethodTraits& traits = method_traits(params.method);
    if (traits.isotropic_only)
        throw InvalidArgument("alpha", text(alpha_x) + "," + text(alpha_y),
                              "one value (alpha_x == alpha_y) for " + std::string(traits.name) + ": " +
                                  std::string(traits.limits));
    if (params.world_space)
        throw InvalidArgument("alpha", text(alpha_x) + "," + text(alpha_y),
                              "one value (alpha_x == alpha_y) in world space, where the normal fixes no tangent");
}

// u1 and u2 in [0, 1); NaN fails the compares.
void check_uniforms(std::size_t index, const std::array<float, 2>& u)
{
    if (!(u[0] >= 0.0f && u[0] < 1.0f && u[1] >= 0.0f && u[1] < 1.0f))
        throw InvalidArgument("uniforms[" + std::to_string(index) + "]", text(u[0]) + "," + text(u[1]),
                              "two numbers in [0, 1)");
}

// eta: 0 (no dielectric) or a relative index, for a method with a dielectric sampler.
void check_eta(const SampleParams& params)
{
    const float eta = params.eta;
    if (eta == 0.0f)
        return;
    if (!(eta > 0.0f) || !std::isfinite(eta) || eta == 1.0f)
        throw InvalidArgument("eta", text(eta),
                              "0 (a conductor, Fresnel 1) or a relative index of refraction: finite, > 0 and != 1");
    const MethodTraits& traits = method_traits(params.method);
    if (!traits.dielectric)
        throw InvalidArgument("eta", text(eta), "0 for " + sampler_name(params) + ": " + std::string(traits.limits));
    const int transport = static_cast<int>(params.transport);
    if (transport < 0 || transport >= int(all_transports.size()))
        throw InvalidArgument("transport", std::to_string(transport), "radiance or importance");
}

// Method::user and user_sampler come together; a user sampler is a tangent-space reflection sampler.
void check_user_sampler(const SampleParams& params)
{
    const bool user = params.method == Method::user;
    if (user && !params.user_sampler)
        throw InvalidArgument("user_sampler", "none", "a UserSampler (UserSampler::load) for method user");
    if (!user && params.user_sampler)
        throw InvalidArgument("method", std::string(method_name(params.method)),
                              "user when user_sampler is set (" + params.user_sampler->name() + ")");
    if (user && params.world_space)
        throw InvalidArgument("world_space", "true",
                              "false for a user sampler (" + params.user_sampler->name() + "): tangent space only");
}

// u3 in [0, 1); NaN fails the compares.
void check_lobe_uniform(std::size_t index, float u)
{
    if (!(u >= 0.0f && u < 1.0f))
        throw InvalidArgument("lobe_uniforms[" + std::to_string(index) + "]", text(u), "a number in [0, 1)");
}

// params with unit view and normal; params must be valid.
SampleParams with_unit_vectors(const SampleParams& params)
{
    SampleParams out = params;
    out.view = unit_vector(params.view);
    out.normal = unit_vector(params.normal);
    return out;
}

} // namespace

std::string_view precision_name(Precision precision)
{
    switch (precision) {
    case Precision::precise: return "precise";
    case Precision::relaxed: return "relaxed";
    }
    return "unknown";
}

std::string_view transport_name(Transport transport)
{
    switch (transport) {
    case Transport::radiance: return "radiance";
    case Transport::importance: return "importance";
    }
    return "unknown";
}

Transport parse_transport(std::string_view name)
{
    return detail::parse_named(name, all_transports, transport_name, "transport");
}

Precision parse_precision(std::string_view name)
{
    return detail::parse_named(name, all_precisions, precision_name, "precision");
}

std::string precision_list()
{
    return detail::name_list(all_precisions, precision_name);
}

std::string_view sequence_name(Sequence sequence)
{
    switch (sequence) {
    case Sequence::philox: return "philox";
    case Sequence::sobol: return "sobol";
    }
    return "unknown";
}

Sequence parse_sequence(std::string_view name)
{
    return detail::parse_named(name, all_sequences, sequence_name, "sequence");
}

std::string sequence_description(Sequence sequence)
{
    if (sequence == Sequence::sobol)
        return "Sobol dimensions 1 and 2 (and 3 for u3) of point index mod 2^32, each Owen-scrambled by Burley's "
               "hash keyed by (seed, dimension, index / 2^32); u = top 24 bits times 2^-24";
    return "Philox2x32-10, key seed, counter (index lo, index hi); u1 word 0, u2 word 1 (u3: word 0 of counter "
           "(index lo, index hi xor 2^31))";
}

float uniform_to_float(double u)
{
    const float f = float(u);
    return (f == 1.0f && u < 1.0) ? std::nextafter(1.0f, 0.0f) : f;
}

Vec3 unit_vector(const Vec3& v)
{
    double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    return {float(v.x / len), float(v.y / len), float(v.z / len)};
}

Vec3 view_from_angles(double theta_degrees, double phi_degrees)
{
    check_angle("theta", theta_degrees, 0.0, 180.0);
    check_angle("phi", phi_degrees, -360.0, 360.0);
    const double to_radians = 3.14159265358979323846 / 180.0;
    double t = theta_degrees * to_radians, p = phi_degrees * to_radians;
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}

std::string sampler_name(const SampleParams& params)
{
    if (params.method == Method::user && params.user_sampler)
        return params.user_sampler->name();
    return std::string(method_name(params.method));
}

bool uses_normal(const SampleParams& params)
{
    return method_traits(params.method).space == Space::world || params.world_space;
}

bool view_above_horizon(const Vec3& view, const Vec3& normal, bool against_normal)
{
    if (!against_normal)
        return view.z >= 0.0f;  // normalizing keeps the sign of z
    Vec3 i = unit_vector(view), n = unit_vector(normal);
    return double(i.x) * n.x + double(i.y) * n.y + double(i.z) * n.z >= 1e-6;  // margin for float rounding
}

bool all_views_above_horizon(const PerSampleInputs& inputs, const SampleParams& params)
{
    bool against_normal = uses_normal(params);
    std::size_t count = std::max(inputs.views.size(), against_normal ? inputs.normals.size() : 0);
    for (std::size_t j = 0; j < std::max<std::size_t>(count, 1); ++j) {
        Vec3 view = inputs.views.empty() ? params.view : inputs.views[j];
        Vec3 normal = inputs.normals.empty() ? params.normal : inputs.normals[j];
        if (!view_above_horizon(view, normal, against_normal))
            return false;
    }
    return true;
}

bool all_isotropic(const PerSampleInputs& inputs, const SampleParams& params)
{
    if (inputs.alphas.empty())
        return params.alpha_x == params.alpha_y;
    for (const auto& a : inputs.alphas)
        if (a[0] != a[1])
            return false;
    return true;
}

void validate(const SampleParams& params)
{
    check_alpha("alpha_x", params.alpha_x);
    check_alpha("alpha_y", params.alpha_y);
    check_isotropic(params, params.alpha_x, params.alpha_y);
    check_direction("view", params.view);
    check_direction("normal", params.normal);
    check_user_sampler(params);
    check_eta(params);
    check_view_visible(params);
}

SampleParams normalized(const SampleParams& params)
{
    validate(params);
    return with_unit_vectors(params);
}

namespace detail {

ValidatedParams validated(const SampleParams& params)
{
    validate(params);
    return ValidatedParams(with_unit_vectors(params));
}

} // namespace detail

void validate(const SampleRange& range)
{
    if (range.seed > max_seed)
        throw InvalidArgument("seed", std::to_string(range.seed),
                              std::string(seed_range) + " = " + std::to_string(max_seed) + " (the generators' 32-bit key)");
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
        check_isotropic(params, a[0], a[1]);
    }
    check_size("uniforms", inputs.uniforms.size());
    for (std::size_t j = 0; j < inputs.uniforms.size(); ++j)
        check_uniforms(j, inputs.uniforms[j]);
    const std::size_t lobe_count = params.eta != 0.0f ? inputs.uniforms.size() : 0;
    if (inputs.lobe_uniforms.size() != lobe_count)
        throw InvalidArgument("lobe_uniforms", std::to_string(inputs.lobe_uniforms.size()) + " entries",
                              params.eta != 0.0f ? "one per entry of uniforms (" + std::to_string(lobe_count) +
                                                       "): a dielectric's third uniform u3"
                                                 : "none without eta (only a dielectric draws a third uniform)");
    for (std::size_t j = 0; j < inputs.lobe_uniforms.size(); ++j)
        check_lobe_uniform(j, inputs.lobe_uniforms[j]);
}

} // namespace ggxcl
