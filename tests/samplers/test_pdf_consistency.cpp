// test_pdf_consistency.cpp - the pdf a sampler returns equals the pdf
// recomputed from the direction alone: on the device (ggx_pdf_bulk, the
// `ggx_pdf_<method>` device functions) and in the double reference; for
// bounded also where both alphas exceed 1 (k < 0).  The pdf of directions
// with a view per sample is the same whatever the chunk size; no directions
// is refused.  On the back end of GGX_TEST_API (backend_fixture.hpp): CTest
// runs it on OpenCL and on Vulkan.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "backend_fixture.hpp"
#include "device_fixture.hpp"
#include "error_bounds.hpp"

namespace {

// Relative errors, float against float (device returned vs device recomputed)
// and float against double (returned vs reference recomputed), which at very
// small alpha and grazing views inherit the conditioning of the half vector.
constexpr ggxtest::ErrorBound recompute_bound{"pdf_o returned vs recomputed from (i, o)", 2e-4, 1e-2};
constexpr ggxtest::ErrorBound pdf_m_bound{"pdf_m returned vs reference pdf of m", 2e-5, 1e-3};
constexpr std::uint64_t samples = 4096;

void check_method(ggxref::Method method, const std::vector<ggxtest::Config>& grid)
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    std::vector<double> device_errors, reference_errors, pdf_m_errors;
    for (const ggxtest::Config& config : grid) {
        ggxcl::SampleParams params = ggxtest::to_library(method, config.params);
        ggxcl::SampleSet s = backend->generate(params, {99, 0, samples},
                                                {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_m,
                                                 ggxcl::Field::pdf_o});
        std::vector<ggxcl::Vec3> directions(samples);
        for (std::size_t j = 0; j < samples; ++j)
            directions[j] = s.o_at(j);
        std::vector<float> recomputed = backend->pdf(params, directions);
        for (std::size_t j = 0; j < samples; ++j) {
            ggxref::Vec3 m = ggxtest::unit(s.m_at(j)), o = ggxtest::unit(s.o_at(j));
            const ggxref::Vec3& i = config.params.i;
            pdf_m_errors.push_back(ggxtest::relative_error(s.pdf_m[j], ggxref::pdf_m(method, config.params, m)));
            if (method == ggxref::Method::ndf && std::fabs(i.x * m.x + i.y * m.y + i.z * m.z) < 1e-2)
                continue;  // pdf_o = pdf_m / (4 |i.m|) is ill-conditioned there (see test_per_sample)
            device_errors.push_back(ggxtest::relative_error(recomputed[j], s.pdf_o[j]));
            reference_errors.push_back(ggxtest::relative_error(s.pdf_o[j], ggxref::pdf_o(method, config.params, o)));
        }
    }
    std::string name = ggxref::method_name(method);
    ggxtest::check_errors(name + " device", recompute_bound, device_errors);
    ggxtest::check_errors(name + " reference", recompute_bound, reference_errors);
    ggxtest::check_errors(name, pdf_m_bound, pdf_m_errors);
}

void check_method(ggxref::Method method) { check_method(method, ggxtest::per_sample_grid(method)); }

} // namespace

TEST_CASE("ndf: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::ndf); }
TEST_CASE("heitz: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::heitz); }
TEST_CASE("heitz2017: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::heitz2017); }
TEST_CASE("caps: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::caps); }
TEST_CASE("caps-iso: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::caps_iso); }
TEST_CASE("bounded: returned pdf equals the pdf recomputed from (i, o)") { check_method(ggxref::Method::bounded); }
TEST_CASE("bounded where both alphas exceed 1 (k < 0): returned pdf equals the pdf recomputed from (i, o)")
{
    check_method(ggxref::Method::bounded, ggxtest::rough_bounded_grid());
}

TEST_CASE("the pdf of directions with a view per sample does not depend on the chunk size")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    const ggxcl::SampleParams p =
        ggxtest::to_library(ggxref::Method::bounded, ggxtest::make_params(0.5, 0.2, 60.0), ggxcl::Precision::precise);
    const ggxcl::SampleSet s = backend->generate(p, {7, 0, samples}, {ggxcl::Field::o});
    std::vector<ggxcl::Vec3> directions(samples);
    ggxcl::PerSampleInputs views;
    for (std::size_t j = 0; j < samples; ++j) {
        directions[j] = s.o_at(j);
        views.views.push_back(ggxcl::unit_vector({0.1f * float(j % 7), -0.2f, 1.0f}));
    }
    const std::uint64_t chunk = backend->chunk_size();
    const std::vector<float> whole = backend->pdf(p, directions, views);
    backend->set_chunk_size(1000);
    const std::vector<float> chunked = backend->pdf(p, directions, views);
    backend->set_chunk_size(chunk);
    CHECK(chunked == whole);
    CHECK(std::count_if(whole.begin(), whole.end(), [](float v) { return v > 0.0f; }) > int(samples / 2));
}

TEST_CASE("no directions is refused")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    const ggxcl::SampleParams p =
        ggxtest::to_library(ggxref::Method::caps, ggxtest::make_params(0.5, 0.5, 30.0), ggxcl::Precision::precise);
    CHECK_THROWS_AS(backend->pdf(p, {}), ggxcl::InvalidArgument);
    CHECK_THROWS_AS(backend->eval(p, {}), ggxcl::InvalidArgument);
}
