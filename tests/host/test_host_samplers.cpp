// test_host_samplers.cpp - the device headers compiled as C++ (ggx_platform.h) on the host:
// every method sample by sample against the double-precision reference, with the per-sample
// tolerances of the device suites (test_per_sample), and against the device's output for the
// same Philox uniforms.  Both are float code from one source; they may differ where the OpenCL
// compiler and the host compiler round differently (OpenCL allows 3 ulp sqrt and 2.5 ulp
// division, the host rounds both correctly; either may contract a * b + c into an fma).
// docs/TESTING.md records how close they are.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "ggx_philox.h"
#include "ggx_samplers.h"
#include "sample_compare.hpp"

namespace {

constexpr std::uint64_t samples_per_config = 2048;
constexpr std::uint64_t seed = 20231122;

ggx_vec3 vec_of(const ggxref::Vec3& v) { return ggx_vec3_make(float(v.x), float(v.y), float(v.z)); }

void store3(std::vector<float>& plane, std::uint64_t count, std::size_t j, ggx_vec3 v)
{
    plane[j] = v.x;
    plane[count + j] = v.y;
    plane[2 * count + j] = v.z;
}

// What the bulk kernel computes for sample j of (seed, params), computed here by the host compiler.
ggxcl::SampleSet host_samples(ggxref::Method method, const ggxref::Params& p, std::uint64_t count)
{
    ggxcl::SampleSet set;
    set.count = count;
    set.m.resize(3 * count), set.o.resize(3 * count);
    set.pdf_m.resize(count), set.pdf_o.resize(count), set.weight.resize(count);
    const ggx_vec3 n = vec_of(p.n), i = vec_of(p.i);
    for (std::size_t j = 0; j < count; ++j) {
        float u1, u2;
        ggx_uniforms(seed, j, &u1, &u2);
        ggx_sample s = ggx_sample_method(int(method), n, i, float(p.ax), float(p.ay), u1, u2);
        store3(set.m, count, j, s.m);
        store3(set.o, count, j, s.o);
        set.pdf_m[j] = s.pdf_m, set.pdf_o[j] = s.pdf_o, set.weight[j] = s.weight;
    }
    return set;
}

// Host against device: angles of m and o, relative pdf errors, absolute weight errors, and how
// many samples agree to the bit in every field.
struct HostDevice {
    ggxtest::SampleErrors errors;
    std::size_t identical = 0, total = 0;
};

void compare_host_device(const ggxcl::SampleSet& h, const ggxcl::SampleSet& d, HostDevice& out)
{
    auto as_double = [](const ggxcl::Vec3& v) { return ggxref::Vec3{v.x, v.y, v.z}; };
    for (std::size_t j = 0; j < h.count; ++j) {
        const ggxref::Vec3 hm = as_double(h.m_at(j)), dm = as_double(d.m_at(j));
        const ggxref::Vec3 ho = as_double(h.o_at(j)), dob = as_double(d.o_at(j));
        out.errors.angle.push_back(std::max(ggxtest::angle_between(hm, dm), ggxtest::angle_between(ho, dob)));
        out.errors.pdf.push_back(ggxtest::relative_error(h.pdf_m[j], d.pdf_m[j]));
        out.errors.pdf.push_back(ggxtest::relative_error(h.pdf_o[j], d.pdf_o[j]));
        out.errors.weight.push_back(std::fabs(h.weight[j] - d.weight[j]));
        const bool same = hm.x == dm.x && hm.y == dm.y && hm.z == dm.z && ho.x == dob.x && ho.y == dob.y &&
                          ho.z == dob.z && h.pdf_m[j] == d.pdf_m[j] && h.pdf_o[j] == d.pdf_o[j] &&
                          h.weight[j] == d.weight[j];
        out.identical += same;
        ++out.total;
    }
}

void check_method(ggxref::Method method)
{
    const std::string name = ggxref::method_name(method);
    ggxtest::SampleErrors against_reference;
    HostDevice against_device;
    for (const ggxtest::Config& config : ggxtest::per_sample_grid(method)) {
        const ggxcl::SampleSet host = host_samples(method, config.params, samples_per_config);
        auto reference = [&](std::size_t, double u1, double u2) { return ggxref::sample(method, config.params, u1, u2); };
        ggxtest::compare_samples(host, seed, reference, method == ggxref::Method::ndf, config.label, against_reference);
        const ggxcl::SampleSet device = ggxtest::device_samples(method, config.params, seed, samples_per_config,
                                                                ggxcl::FieldSet::all());
        compare_host_device(host, device, against_device);
    }
    ggxtest::check_sample_errors(name + " (C++) against the reference", against_reference);
    // ndf's pdf_o = pdf_m / (4 |i.m|) for |i.m| near 0 differs between two float builds as much as
    // between float and double: the worst-sample pdf bound of the reference comparison.
    ggxtest::check_sample_errors(name + " (C++) against the device", against_device.errors);
    MESSAGE(name, ": ", against_device.identical, " of ", against_device.total,
            " samples bit-identical on host and device");
}

} // namespace

TEST_CASE("the device headers compiled as C++ match the reference and the device, every method")
{
    for (ggxref::Method method : ggxref::all_methods) {
        CAPTURE(ggxref::method_name(method));
        check_method(method);
    }
}

TEST_CASE("near -n the device headers compiled as C++ match the reference and the device: alpha 0.05 at 179 degrees, "
          "0.01 at 179.9")
{
    for (ggxref::Method method : {ggxref::Method::heitz, ggxref::Method::caps, ggxref::Method::caps_iso,
                                  ggxref::Method::bounded}) {
        const std::string name = ggxref::method_name(method);
        ggxtest::SampleErrors against_reference;
        HostDevice against_device;
        for (const auto& [alpha, theta] : {std::pair{0.05, 179.0}, std::pair{0.01, 179.9}}) {
            const ggxtest::Config config = ggxtest::as_device_sees(ggxtest::make_params(alpha, alpha, theta));
            const ggxcl::SampleSet host = host_samples(method, config.params, samples_per_config);
            auto reference = [&](std::size_t, double u1, double u2) { return ggxref::sample(method, config.params, u1, u2); };
            ggxtest::compare_samples(host, seed, reference, false, config.label, against_reference);
            compare_host_device(host, ggxtest::device_samples(method, config.params, seed, samples_per_config,
                                                              ggxcl::FieldSet::all()),
                                against_device);
        }
        ggxtest::check_sample_errors(name + " (C++) near -n against the reference", against_reference);
        ggxtest::check_sample_errors(name + " (C++) near -n against the device", against_device.errors);
    }
}

TEST_CASE("negative control: the C++ samples of swapped uniforms fail the comparison")
{
    const ggxtest::Config config = ggxtest::per_sample_grid(ggxref::Method::caps).at(0);
    const ggxcl::SampleSet host = host_samples(ggxref::Method::caps, config.params, samples_per_config);
    ggxtest::SampleErrors errors;
    auto swapped = [&](std::size_t, double u1, double u2) {
        return ggxref::sample(ggxref::Method::caps, config.params, u2, u1);
    };
    ggxtest::compare_samples(host, seed, swapped, false, config.label, errors);
    std::size_t far = 0;
    for (double angle : errors.angle)
        far += angle > ggxtest::angle_bound.maximum;
    CHECK(far > errors.angle.size() / 2);
}

TEST_CASE("Philox compiled as C++ gives the reference's uniforms")
{
    for (std::uint64_t index : {0ull, 7ull, (1ull << 32) - 1, 1ull << 32, ~0ull}) {
        float u1, u2;
        ggx_uniforms(seed, index, &u1, &u2);
        const std::array<double, 2> r = ggxref::uniforms(seed, index);
        CHECK(double(u1) == r[0]);
        CHECK(double(u2) == r[1]);
    }
}
