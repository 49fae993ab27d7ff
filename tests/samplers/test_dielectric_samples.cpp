// test_dielectric_samples.cpp - rough dielectrics sample by sample: every
// exact method's device samples against the reference's dielectric_sample
// from the same three uniforms (m, o, pdf_o, weight; a lobe chosen
// differently only where u3 is within rounding of F); the density recomputed
// from (i, o) on the device against the sampled one and the reference's;
// the third uniform bit for bit against the reference (Philox and Sobol)
// with Sobol's net property; the white furnace's reflectance and
// transmittance against the reference's quadrature in both transports;
// Sampler::eval against dielectric_cos; eta's validation.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "dielectric_grid.hpp"
#include "sample_compare.hpp"

namespace {

using ggxref::Method;
using ggxtest::DielectricConfig;

constexpr Method exact_methods[] = {Method::ndf, Method::heitz, Method::heitz2017, Method::caps, Method::caps_iso};

ggxref::Vec3 as_double(const ggxcl::Vec3& v) { return {v.x, v.y, v.z}; }

// The normal the method works about (caps-iso: the world normal).
ggxref::Vec3 normal_of(Method method, const ggxref::Params& p)
{
    return method == Method::caps_iso ? p.n : ggxref::Vec3{0.0, 0.0, 1.0};
}

// F(i.m) of the reference sample, as its lobe choice saw it (from the view's side).
double fresnel_of(Method method, const DielectricConfig& c, const ggxref::Sample& r)
{
    const ggxref::Vec3 n = normal_of(method, c.params);
    const bool below = ggxref::dot(c.params.i, n) < 0.0;
    const double cos_m = std::fabs(ggxref::dot(c.params.i, r.m));
    return ggxref::fresnel_dielectric(cos_m, below ? 1.0 / double(c.eta) : double(c.eta));
}

struct LobeCount {
    std::size_t compared = 0, flipped = 0, validity_differs = 0;
};

void compare_config(Method method, const DielectricConfig& c, ggxtest::SampleErrors& errors, LobeCount& lobes)
{
    const ggxcl::SampleParams p = ggxtest::dielectric_params(method, c);
    const ggxcl::SampleSet d = ggxtest::sampler().generate(p, {11, 0, 20000}, ggxcl::FieldSet::all());
    const ggxref::Params ref = ggxbridge::reference_params(p);
    const ggxref::Vec3 n = normal_of(method, ref);
    for (std::size_t j = 0; j < d.count; ++j) {
        const double u1 = d.u[j], u2 = d.u[d.count + j], u3 = d.u[2 * d.count + j];
        const ggxref::Sample r = ggxref::dielectric_sample(method, ref, c.eta, !c.importance, u1, u2, u3);
        const ggxref::Vec3 o = as_double(d.o_at(j));
        ++lobes.compared;
        const bool same_side = (ggxref::dot(o, n) > 0.0) == (ggxref::dot(r.o, n) > 0.0);
        if (!same_side) {  // the lobe: only where u3 is within rounding of F
            ++lobes.flipped;
            CHECK(std::fabs(u3 - fresnel_of(method, c, r)) < 1e-4);
            continue;
        }
        const bool valid = r.pdf_o > 0.0, device_valid = d.pdf_o[j] > 0.0f;
        if (!valid || !device_valid) {  // invalid on both sides, but for o within rounding of the surface
            lobes.validity_differs += valid != device_valid;
            continue;
        }
        errors.angle.push_back(std::max(ggxtest::angle_between(as_double(d.m_at(j)), r.m),
                                        ggxtest::angle_between(o, r.o)));
        errors.pdf.push_back(ggxtest::relative_error(d.pdf_o[j], r.pdf_o));
        errors.weight.push_back(std::fabs(d.weight[j] - r.weight));
        if (!std::isfinite(d.pdf_o[j]) || !std::isfinite(d.weight[j]))
            ++errors.non_finite;
    }
}

} // namespace

TEST_CASE("dielectric samples agree with the reference from the same uniforms")
{
    // The bounds of the reflection samplers' test (sample_compare.hpp) hold for both lobes.
    for (Method method : exact_methods) {
        ggxtest::SampleErrors errors;
        LobeCount lobes;
        for (const DielectricConfig& c : ggxtest::dielectric_grid(method)) {
            CAPTURE(c.label);
            compare_config(method, c, errors, lobes);
        }
        const std::string name = ggxref::method_name(method);
        ggxtest::check_sample_errors(name, errors);
        CHECK(lobes.flipped * 1000 <= lobes.compared);
        CHECK(lobes.validity_differs * 1000 <= lobes.compared);
        MESSAGE(name << ": " << lobes.compared << " samples, " << lobes.flipped << " lobe choices within rounding, "
                     << lobes.validity_differs << " valid on one side only");
    }
}

TEST_CASE("the dielectric density recomputed from (i, o) matches the sampled one and the reference's")
{
    for (Method method : exact_methods) {
        std::vector<double> sampled_errors, reference_errors;
        for (const DielectricConfig& c : ggxtest::dielectric_grid(method)) {
            const ggxcl::SampleParams p = ggxtest::dielectric_params(method, c);
            const ggxcl::SampleSet d = ggxtest::sampler().generate(p, {5, 0, 4000}, {ggxcl::Field::o, ggxcl::Field::pdf_o});
            std::vector<ggxcl::Vec3> o(d.count);
            for (std::size_t j = 0; j < d.count; ++j)
                o[j] = d.o_at(j);
            const std::vector<float> recomputed = ggxtest::sampler().pdf(p, o);
            const ggxref::Params ref = ggxbridge::reference_params(p);
            for (std::size_t j = 0; j < d.count; ++j) {
                if (!(d.pdf_o[j] > 0.0f))
                    continue;
                sampled_errors.push_back(ggxtest::relative_error(recomputed[j], d.pdf_o[j]));
                reference_errors.push_back(ggxtest::relative_error(
                    recomputed[j], ggxref::dielectric_pdf_o(method, ref, c.eta, as_double(o[j]))));
            }
        }
        const std::string name = ggxref::method_name(method);
        ggxtest::check_errors(name + " (against the sampled pdf_o)", {"relative error", 1e-3, 5e-2}, sampled_errors);
        ggxtest::check_errors(name + " (against the reference)", {"relative error", 1e-3, 5e-2}, reference_errors);
    }
}

TEST_CASE("the third uniform: Philox and Sobol bit for bit, Sobol's nets, u1 and u2 as a conductor's")
{
    ggxcl::SampleParams p = ggxtest::to_library(Method::caps, ggxtest::make_params(0.3, 0.3, 40.0));
    for (ggxcl::Sequence sequence : ggxcl::all_sequences) {
        p.sequence = sequence;
        const std::uint64_t first = (1ull << 32) - 2048;  // crosses a 2^32 block: Sobol's keys change
        p.eta = 0.0f;
        const ggxcl::SampleSet conductor = ggxtest::sampler().generate(p, {9, first, 4096}, {ggxcl::Field::u});
        p.eta = 1.5f;
        const ggxcl::SampleSet dielectric = ggxtest::sampler().generate(p, {9, first, 4096}, {ggxcl::Field::u});
        REQUIRE(conductor.u.size() == 2 * 4096);
        REQUIRE(dielectric.u.size() == 3 * 4096);
        CHECK(std::equal(conductor.u.begin(), conductor.u.end(), dielectric.u.begin()));
        std::size_t mismatches = 0;
        for (std::size_t j = 0; j < 4096; ++j) {
            const double expected = sequence == ggxcl::Sequence::sobol ? ggxref::lobe_uniform_sobol(9, first + j)
                                                                       : ggxref::lobe_uniform_philox(9, first + j);
            mismatches += double(dielectric.u[2 * 4096 + j]) != expected;
        }
        CAPTURE(ggxcl::sequence_name(sequence));
        CHECK(mismatches == 0);
    }
    // Sobol from the start of a stream: the first 2^m points put one u3 in each interval of 2^-m and
    // form a (1, m, 3)-net with u1, u2 (each box of volume 2^(1-m) holds two points).
    p.sequence = ggxcl::Sequence::sobol;
    const int m = 10;
    const ggxcl::SampleSet d = ggxtest::sampler().generate(p, {3, 0, 1u << m}, {ggxcl::Field::u});
    const std::size_t count = d.count;
    auto cell = [&](std::size_t j, int c, int digits) { return int(d.u[c * count + j] * float(1 << digits)); };
    std::set<int> strata;
    for (std::size_t j = 0; j < count; ++j)
        strata.insert(cell(j, 2, m));
    CHECK(strata.size() == count);
    for (int a = 0; a <= m - 1; ++a)
        for (int b = 0; a + b <= m - 1; ++b) {
            std::map<long, int> boxes;
            for (std::size_t j = 0; j < count; ++j)
                ++boxes[(long(cell(j, 0, a)) << 40) | (long(cell(j, 1, b)) << 20) | cell(j, 2, m - 1 - a - b)];
            CAPTURE(a);
            CAPTURE(b);
            CHECK(boxes.size() == count / 2);
            CHECK(std::all_of(boxes.begin(), boxes.end(), [](const auto& box) { return box.second == 2; }));
        }
}

TEST_CASE("the dielectric white furnace: reflectance and transmittance against the reference's quadrature")
{
    for (Method method : {Method::caps, Method::ndf, Method::caps_iso}) {
        for (const DielectricConfig& config : ggxtest::dielectric_grid(method)) {
            for (bool importance : {false, true}) {
                DielectricConfig c = config;
                c.importance = importance;
                const ggxcl::SampleParams p = ggxtest::dielectric_params(method, c);
                const std::uint64_t n = 1u << 20;
                const ggxcl::FurnaceSums sums = ggxtest::sampler().furnace(p, {21, 0, n});
                const ggxref::DielectricAlbedo truth =
                    ggxref::dielectric_albedo(ggxbridge::reference_params(p), c.eta, !importance);
                const double se = std::sqrt(sums.variance() / double(n));
                CAPTURE(ggxref::method_name(method));
                CAPTURE(c.label);
                CAPTURE(importance);
                CHECK(std::fabs(sums.reflectance() - truth.reflectance) < 5.0 * se + 1e-5);
                CHECK(std::fabs(sums.transmittance() - truth.transmittance) < 5.0 * se + 1e-5);
                CHECK(sums.mean() == doctest::Approx(sums.reflectance() + sums.transmittance()).epsilon(1e-12));
            }
        }
    }
}

TEST_CASE("Sampler::eval of a dielectric against the reference, both transports")
{
    for (bool importance : {false, true})
        for (const DielectricConfig& config : ggxtest::dielectric_grid(Method::caps)) {
            DielectricConfig c = config;
            c.importance = importance;
            const ggxcl::SampleParams p = ggxtest::dielectric_params(Method::caps, c);
            const ggxref::Params ref = ggxbridge::reference_params(p);
            std::vector<ggxcl::Vec3> o;
            for (int k = 0; k < 400; ++k) {  // a spiral over the whole sphere
                const double z = 1.0 - (k + 0.5) / 200.0, r = std::sqrt(1.0 - z * z), phi = 2.39996323 * k;
                o.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
            }
            const std::vector<float> values = ggxtest::sampler().eval(p, o);
            std::vector<double> errors;
            for (std::size_t j = 0; j < o.size(); ++j) {
                const double truth =
                    ggxref::dielectric_cos(ref.i, ggxtest::unit(o[j]), ref.ax, ref.ay, c.eta, !importance);
                errors.push_back(std::fabs(values[j] - truth) / (std::fabs(truth) + 1e-3));
            }
            CAPTURE(c.label);
            ggxtest::check_errors("eval", {"relative error (1e-3 floor)", 5e-4, 5e-3}, errors);
        }
}

TEST_CASE("eta: refused unless 0 or a relative index; bounded refuses it; lobe uniforms only with it")
{
    ggxcl::SampleParams p;
    for (float bad : {1.0f, -1.5f, std::nanf(""), INFINITY}) {
        p.eta = bad;
        CHECK_THROWS_WITH_AS(ggxcl::validate(p), doctest::Contains("eta"), ggxcl::InvalidArgument);
    }
    p.eta = 1.5f;
    p.method = ggxcl::Method::bounded;
    CHECK_THROWS_WITH_AS(ggxcl::validate(p), doctest::Contains("caps"), ggxcl::InvalidArgument);
    p.method = ggxcl::Method::caps;
    ggxcl::PerSampleInputs in;
    in.uniforms = {{0.1f, 0.2f}};
    CHECK_THROWS_WITH_AS(ggxcl::validate(in, p, 1), doctest::Contains("lobe_uniforms"), ggxcl::InvalidArgument);
    in.lobe_uniforms = {1.0f};
    CHECK_THROWS_WITH_AS(ggxcl::validate(in, p, 1), doctest::Contains("lobe_uniforms[0]"), ggxcl::InvalidArgument);
    in.lobe_uniforms = {0.99f};
    CHECK_NOTHROW(ggxcl::validate(in, p, 1));
    // The caller's three uniforms give the sequence's sample for the same numbers.
    const ggxcl::SampleSet drawn = ggxtest::sampler().generate(p, {4, 0, 64}, ggxcl::FieldSet::all());
    in.uniforms.clear();
    in.lobe_uniforms.clear();
    for (std::size_t j = 0; j < 64; ++j) {
        in.uniforms.push_back({drawn.u[j], drawn.u[64 + j]});
        in.lobe_uniforms.push_back(drawn.u[128 + j]);
    }
    const ggxcl::SampleSet given = ggxtest::sampler().generate(p, {4, 0, 64}, ggxcl::FieldSet::all(), in);
    CHECK(given.o == drawn.o);
    CHECK(given.weight == drawn.weight);
    p.eta = 0.0f;
    CHECK_THROWS_WITH_AS(ggxcl::validate(in, p, 64), doctest::Contains("lobe_uniforms"), ggxcl::InvalidArgument);
}

TEST_CASE("a dielectric through the caller's buffers: enqueue (three planes of u) and enqueue_furnace (three of sums)")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    ggxcl::SampleParams p = ggxtest::to_library(Method::heitz, ggxtest::make_params(0.4, 0.4, 150.0));
    p.eta = 1.33f;
    const std::uint32_t n = 3000, stride = 3072;
    ggxcl::DeviceOutputs out;
    out.o = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * stride * sizeof(float));
    out.u = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 2 * stride * sizeof(float));
    CHECK_THROWS_WITH_AS(s.enqueue(s.queue(), p, {6, 0, n}, out, stride), doctest::Contains("outputs.u"),
                         ggxcl::InvalidArgument);
    out.u = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * stride * sizeof(float));
    s.enqueue(s.queue(), p, {6, 0, n}, out, stride).wait();
    std::vector<float> o(3 * stride), u(3 * stride);
    s.queue().enqueueReadBuffer(out.o, CL_TRUE, 0, o.size() * sizeof(float), o.data());
    s.queue().enqueueReadBuffer(out.u, CL_TRUE, 0, u.size() * sizeof(float), u.data());
    const ggxcl::SampleSet host = s.generate(p, {6, 0, n}, {ggxcl::Field::o, ggxcl::Field::u});
    std::size_t differ = 0;
    for (int c = 0; c < 3; ++c)
        for (std::uint32_t j = 0; j < n; ++j)
            differ += o[c * stride + j] != host.o[c * n + j] || u[c * stride + j] != host.u[c * n + j];
    CHECK(differ == 0);

    const std::uint64_t count = 1u << 16;
    const std::size_t items = s.furnace_items(count);
    cl::Buffer sums(s.context(), CL_MEM_READ_WRITE, 3 * items * sizeof(float));
    s.enqueue_furnace(s.queue(), p, {6, 0, count}, sums).wait();
    std::vector<float> partial(3 * items);
    s.queue().enqueueReadBuffer(sums, CL_TRUE, 0, partial.size() * sizeof(float), partial.data());
    double total = 0.0, reflected = 0.0;
    for (std::size_t w = 0; w < items; ++w) {
        total += partial[w];
        reflected += partial[2 * items + w];
    }
    const ggxcl::FurnaceSums fused = s.furnace(p, {6, 0, count});
    CHECK(total == doctest::Approx(fused.sum).epsilon(1e-6));
    CHECK(reflected == doctest::Approx(fused.reflected_sum).epsilon(1e-6));
    CHECK(reflected > 0.0);
    CHECK(reflected < total);
    cl::Buffer two_planes(s.context(), CL_MEM_READ_WRITE, 2 * items * sizeof(float));
    CHECK_THROWS_WITH_AS(s.enqueue_furnace(s.queue(), p, {6, 0, count}, two_planes), doctest::Contains("sums"),
                         ggxcl::InvalidArgument);
}
