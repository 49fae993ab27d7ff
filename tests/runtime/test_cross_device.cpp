// test_cross_device.cpp - the same range drawn on two OpenCL implementations
// (the selected device, and the first device of every other platform: PoCL,
// Mesa rusticl with RUSTICL_ENABLE=llvmpipe, a GPU driver) agrees sample by
// sample.  Bits may differ (each implementation has its own sqrt, sin and
// rounding of contractions); each side is within the per-sample bounds of
// docs/TESTING.md of the reference, so the two agree within twice those
// bounds: angle 4e-5 / 4e-3 rad, pdf relative 4e-4 / 2e-2, weight 4e-5 /
// 4e-3 (99.9% of the samples / the worst), every method, precise mode.
// Needs a second implementation (scripts/install-deps.sh installs PoCL and
// rusticl): skipped without one (skip.hpp).
#include <doctest/doctest.h>

#include <cstdlib>

#include "sample_compare.hpp"
#include "skip.hpp"

namespace {

constexpr std::uint64_t samples_per_config = 2048;
constexpr std::uint64_t seed = 77;

constexpr ggxtest::ErrorBound twice_angle{"angle between the implementations' m and o (rad)", 4e-5, 4e-3};
constexpr ggxtest::ErrorBound twice_pdf{"relative difference of pdf_m and pdf_o", 4e-4, 2e-2};
constexpr ggxtest::ErrorBound twice_weight{"absolute difference of weight", 4e-5, 4e-3};

// The first device of each platform other than the selected device's.
std::vector<ggxcl::DeviceInfo> other_implementations()
{
    ::setenv("RUSTICL_ENABLE", "llvmpipe", 0);  // rusticl lists no CPU device without it
    const std::string selected = ggxtest::sampler().device().getInfo<CL_DEVICE_NAME>();
    const cl::Platform selected_platform(ggxtest::sampler().device().getInfo<CL_DEVICE_PLATFORM>());
    std::vector<ggxcl::DeviceInfo> others;
    for (const ggxcl::DeviceInfo& d : ggxcl::list_devices()) {
        bool same_platform = d.platform == selected_platform.getInfo<CL_PLATFORM_NAME>();
        bool platform_seen = false;
        for (const ggxcl::DeviceInfo& o : others)
            platform_seen = platform_seen || o.platform == d.platform;
        if (!same_platform && !platform_seen)
            others.push_back(d);
    }
    return others;
}

// The other implementation's sample j as a reference sample.
ggxref::Sample as_reference(const ggxcl::SampleSet& s, std::size_t j)
{
    ggxref::Sample r;
    ggxcl::Vec3 m = s.m_at(j), o = s.o_at(j);
    r.m = {m.x, m.y, m.z};
    r.o = {o.x, o.y, o.z};
    r.pdf_m = s.pdf_m[j];
    r.pdf_o = s.pdf_o[j];
    r.weight = s.weight[j];
    return r;
}

void compare_with(ggxcl::Sampler& other, ggxref::Method method, ggxcl::Precision precision)
{
    ggxtest::SampleErrors errors;
    for (const ggxtest::Config& config : ggxtest::per_sample_grid(method)) {
        ggxcl::SampleSet here = ggxtest::device_samples(method, config.params, seed, samples_per_config,
                                                        ggxcl::FieldSet::all(), precision);
        ggxcl::SampleSet there = other.generate(ggxtest::to_library(method, config.params, precision),
                                                {seed, 0, samples_per_config}, ggxcl::FieldSet::all());
        auto reference = [&](std::size_t j, double, double) { return as_reference(there, j); };
        ggxtest::compare_samples(here, seed, reference, method == ggxref::Method::ndf, config.label, errors);
    }
    ggxtest::check_sample_errors(std::string(ggxref::method_name(method)) + " " +
                                     std::string(ggxcl::precision_name(precision)),
                                 errors, twice_angle, twice_pdf, twice_weight);
}

} // namespace

TEST_CASE("every method draws the same samples on every implementation, within twice the per-sample bounds")
{
    std::vector<ggxcl::DeviceInfo> others = other_implementations();
    INFO("selected: " << ggxtest::sampler().device_name());
    if (!ggxtest::skip_unless(!others.empty(), "needs a second OpenCL implementation beside " +
                                                   ggxtest::sampler().device_name() +
                                                   " (PoCL, or rusticl: apt-get install pocl-opencl-icd "
                                                   "mesa-opencl-icd)"))
        return;
    for (const ggxcl::DeviceInfo& device : others) {
        ggxcl::Sampler other(device);
        MESSAGE("against " << device.label());
        for (ggxref::Method method : ggxref::all_methods)
            compare_with(other, method, ggxcl::Precision::precise);
    }
}
