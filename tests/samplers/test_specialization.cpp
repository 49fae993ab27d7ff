// test_specialization.cpp - the program variants the runtime picks from a
// request (isotropic or not, views below the horizon supported or not, see
// kernels/ggx_bulk.cl) compute what the general program computes:
//  - where both apply, the specialized variant's samples are bit-identical
//    to those of the general one (reached through per-sample device buffers
//    without promises) in the precise mode, and within the
//    per-sample bounds in relaxed mode (fast-math reassociates each form
//    differently);
//  - views below the horizon select the general form, which matches the
//    reference sample by sample (at moderate depths: views far below the
//    horizon with small alpha narrow the cap to 1 + vz ~ 1e-4 and float loses
//    digits there in every form; the stability map covers that);
//  - negative control: a false promise (views_above_horizon for views that
//    are not) selects the cheap form and visibly breaks the pdf there;
//  - the unguarded variant (SampleParams::guards = false) equals the guarded one
//    inside the domain bit for bit, and outside it (the view exactly
//    opposite the normal) only the guarded one gives the fallback.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>


#include "sample_compare.hpp"

namespace {

using ggxref::Method;

constexpr std::uint64_t seed = 99;
constexpr std::uint32_t count = 4096;
// Below the horizon a few samples have i.m -> 0, where pdf_m = 4 (i.m) pdf_o
// inherits the cancellation of i.m (heitz: 4.2e-2 at worst, measured).
constexpr ggxtest::ErrorBound below_horizon_pdf_bound{"relative error of pdf_m and pdf_o", 2e-4, 1e-1};

cl::Buffer planar_buffer(const std::vector<float>& values)
{
    ggxcl::Sampler& s = ggxtest::sampler();
    return cl::Buffer(s.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, values.size() * sizeof(float),
                      const_cast<float*>(values.data()));
}

std::vector<float> read(const cl::Buffer& buffer, std::size_t floats)
{
    std::vector<float> host(floats);
    ggxtest::sampler().queue().enqueueReadBuffer(buffer, CL_TRUE, 0, floats * sizeof(float), host.data());
    return host;
}

// All fields of samples 0..count-1, with the view and alpha read per sample
// from device buffers (the general program unless `promise_above`).
ggxcl::SampleSet samples_from_buffers(const ggxcl::SampleParams& p, bool promise_above)
{
    ggxcl::Sampler& s = ggxtest::sampler();
    std::vector<float> views(3 * count), alphas(2 * count);
    for (std::uint32_t j = 0; j < count; ++j) {
        views[j] = p.view.x, views[count + j] = p.view.y, views[2 * count + j] = p.view.z;
        alphas[j] = p.alpha_x, alphas[count + j] = p.alpha_y;
    }
    ggxcl::DeviceInputs in;
    in.view = planar_buffer(views);
    in.alpha = planar_buffer(alphas);
    in.views_above_horizon = promise_above;
    ggxcl::DeviceOutputs out;
    cl::Buffer* buffers[] = {&out.m, &out.o, &out.pdf_m, &out.pdf_o, &out.weight};
    for (cl::Buffer* b : buffers)
        *b = cl::Buffer(s.context(), CL_MEM_WRITE_ONLY, 3 * count * sizeof(float));
    s.enqueue(s.queue(), p, {seed, 0, count}, out, 0, in).wait();
    ggxcl::SampleSet set;
    set.count = count;
    set.m = read(out.m, 3 * count);
    set.o = read(out.o, 3 * count);
    set.pdf_m = read(out.pdf_m, count);
    set.pdf_o = read(out.pdf_o, count);
    set.weight = read(out.weight, count);
    return set;
}

ggxcl::SampleParams params_of(Method method, double ax, double ay, double theta, ggxcl::Precision precision)
{
    return ggxcl::normalized(ggxtest::to_library(method, ggxtest::make_params(ax, ay, theta), precision));
}

void check_bit_identical(const ggxcl::SampleSet& a, const ggxcl::SampleSet& b)
{
    CHECK(a.m == b.m);
    CHECK(a.o == b.o);
    CHECK(a.pdf_m == b.pdf_m);
    CHECK(a.pdf_o == b.pdf_o);
    CHECK(a.weight == b.weight);
}

ggxref::Vec3 as_double(const ggxcl::Vec3& v)
{
    return {v.x, v.y, v.z};
}

// The same computation up to float rounding, within the per-sample bounds:
// the compiler contracts and folds the uniform and the per-sample forms
// differently, and the conditioning of a few samples (Heitz's disk rim)
// amplifies the ulps.
void check_same_samples(const std::string& label, const ggxcl::SampleSet& a, const ggxcl::SampleSet& b)
{
    std::vector<double> angle, pdf, weight;
    for (std::size_t j = 0; j < a.count; ++j) {
        angle.push_back(std::max(ggxtest::angle_between(as_double(a.m_at(j)), as_double(b.m_at(j))),
                                 ggxtest::angle_between(as_double(a.o_at(j)), as_double(b.o_at(j)))));
        pdf.push_back(ggxtest::relative_error(a.pdf_m[j], b.pdf_m[j]));
        pdf.push_back(ggxtest::relative_error(a.pdf_o[j], b.pdf_o[j]));
        weight.push_back(std::fabs(a.weight[j] - b.weight[j]));
    }
    ggxtest::check_errors(label, ggxtest::angle_bound, angle);
    ggxtest::check_errors(label, ggxtest::pdf_bound, pdf);
    ggxtest::check_errors(label, ggxtest::weight_bound, weight);
}

} // namespace

TEST_CASE("specialized variants give the general variant's samples")
{
    for (Method method : ggxref::all_methods)
        for (ggxcl::Precision precision : ggxtest::all_precisions)
            for (double theta : {0.0, 60.0, 89.0}) {
                ggxcl::SampleParams p = params_of(method, 0.3, 0.3, theta, precision);
                ggxcl::SampleSet specialized =
                    ggxtest::sampler().generate(p, {seed, 0, count}, ggxcl::FieldSet::all());
                std::string label = std::string(ggxref::method_name(method)) + " " +
                                    std::string(ggxcl::precision_name(precision)) + " theta " + std::to_string(theta);
                ggxcl::SampleSet general = samples_from_buffers(p, false);
                if (precision == ggxcl::Precision::relaxed) {
                    check_same_samples(label, specialized, general);
                } else {
                    CAPTURE(label);
                    check_bit_identical(specialized, general);
                }
            }
}

TEST_CASE("views below the horizon select the general form, which matches the reference")
{
    const ggxcl::Precision precision = ggxcl::Precision::precise;
    for (Method method : {Method::ndf, Method::heitz, Method::caps, Method::caps_iso, Method::bounded}) {
        ggxtest::SampleErrors errors;
        for (double alpha : {0.3, 0.6, 1.0})
            for (double theta : {100.0, 120.0, 135.0}) {
                ggxref::Params params = ggxtest::make_params(alpha, alpha, theta);
                ggxcl::SampleParams p = params_of(method, alpha, alpha, theta, precision);
                params.i = {p.view.x, p.view.y, p.view.z};
                params.ax = params.ay = p.alpha_x;
                ggxcl::SampleSet d = ggxtest::sampler().generate(p, {seed, 0, count}, ggxcl::FieldSet::all());
                auto reference = [&](std::size_t, double u1, double u2) {
                    return ggxref::sample(method, params, u1, u2);
                };
                ggxtest::compare_samples(d, seed, reference, method == Method::ndf, ggxtest::describe(params),
                                         errors);
            }
        ggxtest::check_sample_errors(std::string(ggxref::method_name(method)) + " below the horizon", errors,
                                     ggxtest::angle_bound, below_horizon_pdf_bound);
    }
}

TEST_CASE("negative control: a false above-horizon promise breaks the pdf of grazing-from-below views")
{
    // iz = cos 178 deg with alpha 0.02: iz + t(i) is 2.4e-7, which the plain form loses to cancellation.
    ggxcl::SampleParams p = params_of(Method::caps, 0.02, 0.02, 178.0, ggxcl::Precision::precise);
    ggxcl::SampleSet honest = samples_from_buffers(p, false);
    ggxcl::SampleSet broken = samples_from_buffers(p, true);
    ggxref::Params params = ggxtest::make_params(0.02, 0.02, 178.0);
    params.i = {p.view.x, p.view.y, p.view.z};
    params.ax = params.ay = p.alpha_x;
    std::size_t honest_bad = 0, broken_bad = 0;
    for (std::size_t j = 0; j < count; ++j) {
        std::array<double, 2> u = ggxref::uniforms(seed, j);
        double reference = ggxref::sample(Method::caps, params, u[0], u[1]).pdf_o;
        honest_bad += ggxtest::relative_error(honest.pdf_o[j], reference) > 1e-2;
        broken_bad += ggxtest::relative_error(broken.pdf_o[j], reference) > 1e-2;
    }
    CHECK(honest_bad == 0);
    CHECK(broken_bad > count / 2);
}

TEST_CASE("the unguarded variant: the same bits inside the domain, no fallback outside")
{
    auto& s = ggxtest::sampler();
    // m (3 planes) then pdf_m of each sample.
    // The view of every sample, as per-sample inputs (3 planes): the library refuses a uniform view
    // opposite the normal for caps (nothing is visible from there), the kernels meet it per sample.
    auto samples = [&](ggxcl::Vec3 view, bool guarded) {
        ggxcl::SampleParams p{ggxcl::Method::caps, 0.4f, 0.4f, ggxcl::view_from_angles(50, 0)};
        p.guards = guarded;
        ggxcl::DeviceOutputs out;
        out.m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * count * sizeof(float));
        out.pdf_m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, count * sizeof(float));
        std::vector<float> planes(3 * count);
        for (std::size_t j = 0; j < count; ++j) {
            planes[j] = view.x;
            planes[count + j] = view.y;
            planes[2 * count + j] = view.z;
        }
        ggxcl::DeviceInputs inputs;
        inputs.view = cl::Buffer(s.context(), planes.begin(), planes.end(), true);
        const ggxcl::SampleRange range{seed, 0, count};
        s.enqueue(s.queue(), p, range, out, 0, inputs).wait();
        std::vector<float> values(4 * count);
        s.queue().enqueueReadBuffer(out.m, CL_TRUE, 0, 3 * count * sizeof(float), values.data());
        s.queue().enqueueReadBuffer(out.pdf_m, CL_TRUE, 0, count * sizeof(float), values.data() + 3 * count);
        return values;
    };
    const ggxcl::Vec3 inside = ggxcl::view_from_angles(50, 0), opposite{0.0f, 0.0f, -1.0f};
    CHECK(samples(inside, false) == samples(inside, true));
    const std::vector<float> guarded = samples(opposite, true), unguarded = samples(opposite, false);
    std::vector<float> fallback(4 * count, 0.0f);  // m = (0, 0, 1), pdf_m = 0
    std::fill(fallback.begin() + 2 * count, fallback.begin() + 3 * count, 1.0f);
    CHECK(guarded == fallback);
    CHECK(std::any_of(unguarded.begin(), unguarded.end(), [](float v) { return !std::isfinite(v); }));
}
