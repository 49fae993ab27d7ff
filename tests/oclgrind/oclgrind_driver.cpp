// oclgrind_driver.cpp - the library's kernels on small counts, for
// test_oclgrind to run under Oclgrind (which checks every memory access,
// data race and uninitialized value of every kernel).  The command line
// cannot reach all of them (per-sample parameters, the pdf kernels, the
// fused furnace, world space, user kernels), so this program drives them
// through ggxcl::Sampler and build_user_program, checks that each result is
// sane (finite, unit vectors, non-negative densities, sums equal to the
// stored weights, user kernel bits equal to the runtime's), and prints one
// line per check group on stdout.  On success it prints nothing on stderr
// (test_oclgrind counts any stderr text as an Oclgrind report); a failed
// check prints "FAIL ..." on stderr and makes the exit status 1.
//
//   oclgrind_driver CASE [COUNT]     CASE: per-sample, pdf, furnace, world, user, stress
//
// COUNT (default 1000) is the number of samples per launch; 1000 is three
// whole work-groups of 256 and a partial one, so both the main and the
// `_tail` kernels run.  For `stress` it is the stride through the stress
// grid's cases (every COUNT-th case runs).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "stress_grid.hpp"
#include "stress_run.hpp"
#include "user_samples.hpp"

namespace {

using ggxcl::Method;
using ggxcl::Precision;
using ggxcl::Vec3;

int failures = 0;

void check(bool ok, const std::string& what)
{
    if (ok)
        return;
    if (++failures <= 20)
        std::cerr << "FAIL " << what << "\n";
}

const Precision modes[] = {Precision::precise, Precision::relaxed};

std::string label(Method method, Precision precision)
{
    return std::string(ggxcl::method_name(method)) + " " + std::string(ggxcl::precision_name(precision));
}

double length(const Vec3& v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

Vec3 unit(double x, double y, double z)
{
    return ggxcl::unit_vector({float(x), float(y), float(z)});
}

// A direction at angle theta (degrees) from n with a random azimuth.
Vec3 around(const Vec3& n, double theta_degrees, std::mt19937& rng)
{
    const double pi = 3.14159265358979323846;
    double phi = std::uniform_real_distribution<double>(0.0, 2.0 * pi)(rng);
    double t = theta_degrees * pi / 180.0;
    // An orthonormal basis (t1, t2, n).
    double nx = n.x, ny = n.y, nz = n.z;
    double ax = std::fabs(nx) < 0.9 ? 1.0 : 0.0, ay = ax == 1.0 ? 0.0 : 1.0, az = 0.0;
    double t1x = ay * nz - az * ny, t1y = az * nx - ax * nz, t1z = ax * ny - ay * nx;
    double l = std::sqrt(t1x * t1x + t1y * t1y + t1z * t1z);
    t1x /= l, t1y /= l, t1z /= l;
    double t2x = ny * t1z - nz * t1y, t2y = nz * t1x - nx * t1z, t2z = nx * t1y - ny * t1x;
    double s = std::sin(t), c = std::cos(t), cp = std::cos(phi), sp = std::sin(phi);
    return unit(s * cp * t1x + s * sp * t2x + c * nx, s * cp * t1y + s * sp * t2y + c * ny,
                s * cp * t1z + s * sp * t2z + c * nz);
}

// Per-sample inputs: views 0..max_theta degrees from the normal(s), alphas
// 0.05..1 (isotropic when asked), normals over the sphere when asked.
ggxcl::PerSampleInputs per_sample_inputs(std::uint64_t count, double max_theta, bool isotropic, bool normals,
                                         unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    ggxcl::PerSampleInputs in;
    for (std::uint64_t j = 0; j < count; ++j) {
        Vec3 n{0.0f, 0.0f, 1.0f};
        if (normals) {
            double z = 2.0 * uniform(rng) - 1.0, phi = 6.283185307179586 * uniform(rng), r = std::sqrt(1.0 - z * z);
            n = unit(r * std::cos(phi), r * std::sin(phi), z);
            in.normals.push_back(n);
        }
        in.views.push_back(around(n, max_theta * uniform(rng), rng));
        float ax = float(0.05 + 0.95 * uniform(rng)), ay = isotropic ? ax : float(0.05 + 0.95 * uniform(rng));
        in.alphas.push_back({ax, ay});
    }
    return in;
}

// m and o unit, everything finite, densities and weight >= 0.
void check_samples(const ggxcl::SampleSet& s, std::uint64_t count, const std::string& what)
{
    check(s.count == count && s.m.size() == 3 * count && s.o.size() == 3 * count && s.pdf_m.size() == count &&
              s.pdf_o.size() == count && s.weight.size() == count,
          what + ": sizes");
    if (s.count != count || s.weight.size() != count)
        return;
    std::uint64_t bad = 0, positive = 0;
    for (std::size_t j = 0; j < count; ++j) {
        Vec3 m = s.m_at(j), o = s.o_at(j);
        bool ok = std::fabs(length(m) - 1.0) < 1e-4 && std::fabs(length(o) - 1.0) < 1e-4 &&
                  std::isfinite(s.pdf_m[j]) && s.pdf_m[j] >= 0.0f && std::isfinite(s.pdf_o[j]) &&
                  s.pdf_o[j] >= 0.0f && std::isfinite(s.weight[j]) && s.weight[j] >= 0.0f;
        bad += !ok;
        positive += s.pdf_o[j] > 0.0f;
    }
    check(bad == 0, what + ": " + std::to_string(bad) + " samples not unit, not finite or negative");
    check(positive > count / 2, what + ": only " + std::to_string(positive) + " samples with pdf_o > 0");
}

// The pdf kernel on the sampled directions gives back pdf_o (99% within 1e-3 relative).
void check_pdf_again(ggxcl::Sampler& sampler, const ggxcl::SampleParams& p, const ggxcl::SampleSet& s,
                     const ggxcl::PerSampleInputs& in, const std::string& what)
{
    std::vector<Vec3> directions(s.count);
    for (std::size_t j = 0; j < s.count; ++j)
        directions[j] = s.o_at(j);
    std::vector<float> again = sampler.pdf(p, directions, in);
    check(again.size() == s.count, what + ": pdf count");
    if (again.size() != s.count)
        return;
    std::uint64_t usable = 0, close = 0, not_finite = 0;
    for (std::size_t j = 0; j < s.count; ++j) {
        not_finite += !std::isfinite(again[j]);
        // heitz2017 does not support views below the horizon (docs/STABILITY.md): its pdf_o is wrong there.
        const Vec3 i = in.views.empty() ? p.view : in.views[j];
        const Vec3 n = in.normals.empty() ? (ggxcl::uses_normal(p) ? p.normal : Vec3{}) : in.normals[j];
        if (p.method == Method::heitz2017 && i.x * n.x + i.y * n.y + i.z * n.z < 0.0f)
            continue;
        if (s.pdf_o[j] > 0.0f) {
            ++usable;
            close += std::fabs(double(again[j]) - s.pdf_o[j]) <= 1e-3 * s.pdf_o[j];
        }
    }
    check(not_finite == 0, what + ": " + std::to_string(not_finite) + " pdfs not finite");
    check(close >= usable * 99 / 100, what + ": recomputed pdf matches pdf_o for " + std::to_string(close) + " of " +
                                          std::to_string(usable));
}

ggxcl::SampleParams params_of(Method method, Precision precision)
{
    ggxcl::SampleParams p{method, 0.3f, method == Method::caps_iso ? 0.3f : 0.15f, ggxcl::view_from_angles(60, 20)};
    p.precision = precision;
    return p;
}

// generate with per-sample views and alphas (caps-iso: and normals), all
// fields, then the pdf kernel with the same per-sample inputs: in precise
// mode the general program (views to 120 degrees, anisotropic), in relaxed
// mode the specialized one (views above the horizon, isotropic).  (Every
// program variant is a compile under Oclgrind, about half a second.)
void run_per_sample(ggxcl::Sampler& sampler, std::uint64_t count)
{
    for (Method method : ggxcl::all_methods)
        for (Precision precision : modes) {
            const bool general = precision == Precision::precise;
            const bool iso = method == Method::caps_iso || !general;
            ggxcl::PerSampleInputs in =
                per_sample_inputs(count, general ? 120.0 : 85.0, iso, method == Method::caps_iso, 7u + general);
            ggxcl::SampleParams p = params_of(method, precision);
            std::string what = "per-sample " + label(method, precision) + (general ? " general" : " specialized");
            ggxcl::SampleSet s = sampler.generate(p, {11, 1000003, count}, ggxcl::FieldSet::all(), in);
            check_samples(s, count, what);
            check_pdf_again(sampler, p, s, in, what);
            std::cout << "ok " << what << "\n";
        }
}

// The pdf kernel with uniform parameters, on directions over the whole sphere.
void run_pdf(ggxcl::Sampler& sampler, std::uint64_t count)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<Vec3> directions;
    for (std::uint64_t j = 0; j < count; ++j) {
        double z = 2.0 * uniform(rng) - 1.0, phi = 6.283185307179586 * uniform(rng), r = std::sqrt(1.0 - z * z);
        directions.push_back(unit(r * std::cos(phi), r * std::sin(phi), z));
    }
    for (Method method : ggxcl::all_methods)
        for (Precision precision : modes) {
            ggxcl::SampleParams p = params_of(method, precision);
            std::vector<float> pdf = sampler.pdf(p, directions);
            std::uint64_t bad = 0, positive = 0;
            for (float v : pdf) {
                bad += !(std::isfinite(v) && v >= 0.0f);
                positive += v > 0.0f;
            }
            const std::string what = "pdf " + label(method, precision);
            check(pdf.size() == count, what + ": count");
            check(bad == 0, what + ": " + std::to_string(bad) + " pdfs not finite or negative");
            check(positive > count / 4, what + ": only " + std::to_string(positive) + " positive pdfs");
            std::cout << "ok " << what << "\n";
        }
}

// Planar copies of per-sample inputs in device buffers (DeviceInputs).
ggxcl::DeviceInputs device_inputs(const cl::Context& context, const ggxcl::PerSampleInputs& in)
{
    const std::size_t count = in.views.size();
    auto upload = [&](const std::vector<float>& planar) {
        return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, planar.size() * sizeof(float),
                          const_cast<float*>(planar.data()));
    };
    auto planes3 = [&](const std::vector<Vec3>& v) {
        std::vector<float> planar(3 * count);
        for (std::size_t j = 0; j < count; ++j)
            planar[j] = v[j].x, planar[count + j] = v[j].y, planar[2 * count + j] = v[j].z;
        return planar;
    };
    std::vector<float> alphas(2 * count);
    for (std::size_t j = 0; j < count; ++j)
        alphas[j] = in.alphas[j][0], alphas[count + j] = in.alphas[j][1];
    ggxcl::DeviceInputs inputs;
    inputs.view = upload(planes3(in.views));
    inputs.alpha = upload(alphas);
    if (!in.normals.empty())
        inputs.normal = upload(planes3(in.normals));
    return inputs;
}

// The partial sums of one enqueue_furnace launch, added in double: (sum, sum of squares).
std::pair<double, double> guarded_furnace(ggxcl::Sampler& sampler, const ggxcl::SampleParams& p,
                                          const ggxcl::SampleRange& range, const ggxcl::DeviceInputs& inputs)
{
    const std::size_t items = sampler.furnace_items(range.count);
    cl::Buffer sums(sampler.context(), CL_MEM_WRITE_ONLY, 2 * items * sizeof(float));
    sampler.enqueue_furnace(sampler.queue(), p, range, sums, inputs);
    std::vector<float> partial(2 * items);
    sampler.queue().enqueueReadBuffer(sums, CL_TRUE, 0, partial.size() * sizeof(float), partial.data());
    double sum = 0.0, squares = 0.0;
    for (std::size_t w = 0; w < items; ++w)
        sum += partial[w], squares += partial[items + w];
    return {sum, squares};
}

bool close_sums(double a, double b) { return std::fabs(a - b) <= 1e-4 * std::fabs(b) + 1e-6; }

// The fused furnace kernel, with work-groups of 64 so that COUNT = 1001
// (126 work-items of 8 samples, the last one partial) spans two groups:
// with uniform parameters unguarded (Sampler::furnace) and guarded
// (enqueue_furnace), whose sums agree, in precise and
// relaxed mode; with per-sample buffers (relaxed mode), guarded, whose sum
// equals that of the stored weights of the same samples.
void run_furnace(ggxcl::Sampler& sampler, std::uint64_t count)
{
    sampler.set_work_group_size(64);
    const ggxcl::SampleRange range{9, 77, count};
    for (Method method : ggxcl::all_methods) {
        for (Precision precision : modes) {
            ggxcl::SampleParams p = params_of(method, precision);
            const std::string what = "furnace " + label(method, precision) + " uniform";
            ggxcl::FurnaceSums sums = sampler.furnace(p, range);
            std::pair<double, double> guarded = guarded_furnace(sampler, p, range, {});
            check(sums.count == count, what + ": count");
            check(std::isfinite(sums.sum) && sums.sum > 0.0, what + ": sum");
            check(close_sums(guarded.first, sums.sum) && close_sums(guarded.second, sums.sum_of_squares),
                  what + ": guarded sums " + std::to_string(guarded.first) + " vs unguarded " +
                      std::to_string(sums.sum));
            std::cout << "ok " << what << " (" << sampler.furnace_items(count) << " work-items)\n";
        }
        ggxcl::SampleParams p = params_of(method, Precision::relaxed);
        const std::string what = "furnace " + label(method, Precision::relaxed) + " per-sample";
        ggxcl::PerSampleInputs in =
            per_sample_inputs(count, 85.0, method == Method::caps_iso, method == Method::caps_iso, 5);
        ggxcl::SampleSet s = sampler.generate(p, range, {ggxcl::Field::weight}, in);
        double stored = 0.0;
        for (float w : s.weight)
            stored += w;
        std::pair<double, double> guarded = guarded_furnace(sampler, p, range, device_inputs(sampler.context(), in));
        check(close_sums(guarded.first, stored),
              what + ": sum " + std::to_string(guarded.first) + " vs stored weights " + std::to_string(stored));
        std::cout << "ok " << what << "\n";
    }
    sampler.set_work_group_size(0);
}

// World space (SampleParams::world_space) for every method: in precise
// mode a uniform tilted normal and view (o above the normal's horizon for
// most samples), in relaxed mode per-sample normals and views; the
// world-space pdf kernel gives back pdf_o.
void run_world(ggxcl::Sampler& sampler, std::uint64_t count)
{
    for (Method method : ggxcl::all_methods)
        for (Precision precision : modes) {
            ggxcl::SampleParams p = params_of(method, precision);
            p.alpha_y = p.alpha_x;
            p.world_space = true;
            p.normal = unit(0.3, -0.5, 0.6);
            std::mt19937 rng(1);
            p.view = around(p.normal, 50.0, rng);
            ggxcl::PerSampleInputs in;
            if (precision == Precision::relaxed)
                in = per_sample_inputs(count, 85.0, true, true, 13);
            const std::string what =
                "world " + label(method, precision) + (in.views.empty() ? " uniform" : " per-sample");
            ggxcl::SampleSet s = sampler.generate(p, {2, 40, count}, ggxcl::FieldSet::all(), in);
            check_samples(s, count, what);
            check_pdf_again(sampler, p, s, in, what);
            std::uint64_t above = 0;
            for (std::size_t j = 0; j < count && s.o.size() == 3 * count; ++j) {
                const Vec3 o = s.o_at(j), n = in.normals.empty() ? p.normal : in.normals[j];
                above += o.x * n.x + o.y * n.y + o.z * n.z > 0.0f;
            }
            check(above > count / 2, what + ": only " + std::to_string(above) + " o above the normal's horizon");
            std::cout << "ok " << what << "\n";
        }
}

// A user kernel that includes ggx_samplers.h (build_user_program) and calls
// ggx_uniforms + ggx_sample_method gives the bits of Sampler::enqueue:
// every method, half of them in precise and half in relaxed mode.
void run_user(ggxcl::Sampler& sampler, std::uint64_t count)
{
    const ggxcl::SampleRange range{0xabcd5678ull, (1ull << 33) + 17, count};
    for (Method method : ggxcl::all_methods)
        for (Precision precision : modes) {
            // Half the methods in each mode: every program variant is a compile under Oclgrind.
            if ((int(method) % 2 == 0) != (precision == Precision::precise))
                continue;
            ggxcl::SampleParams p{method, 0.2f, method == Method::caps_iso ? 0.2f : 0.45f,
                                  ggxcl::view_from_angles(63, 30)};
            p.precision = precision;
            std::string options = ggxcl::precision_options(sampler.device(), precision);
            if (method == Method::caps_iso) {
                p.normal = {0.0f, 0.6f, 0.8f};  // tilted: the general form (n = z would need GGX_NORMAL_IS_Z)
                p.view = {0.3f, -0.2f, 0.9f};
            }
            const std::string what = "user kernel " + label(method, precision);
            cl::Program program = ggxcl::build_user_program(sampler.context(), sampler.device(),
                                                            ggxtest::user_samples_source(true), options);
            ggxtest::SamplePlanes mine = ggxtest::run_user_samples(sampler, program, p, range);
            ggxtest::SamplePlanes runtime = ggxtest::enqueue_samples(sampler, sampler.queue(), p, range);
            std::size_t differ = 0;
            for (std::size_t k = 0; k < mine.size() && k < runtime.size(); ++k)
                differ += std::memcmp(&mine[k], &runtime[k], sizeof(float)) != 0;
            check(mine.size() == 9 * count && runtime.size() == 9 * count, what + ": sizes");
            check(differ == 0, what + ": " + std::to_string(differ) + " floats differ from Sampler::enqueue");
            std::cout << "ok " << what << "\n";
        }
}

// kernels/ggx_stress.cl through device_stress_map (what `ggx stress` runs),
// on every `stride`-th case of the stress grid, relaxed mode (the
// command line's run covers precise mode on the whole grid): no NaN or Inf,
// and every case counted.
void run_stress(ggxcl::Sampler& sampler, std::uint64_t stride)
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (Method method : ggxcl::all_methods)
        for (Precision precision : {Precision::relaxed}) {
            std::vector<ggxapp::StressCase> all = ggxapp::stress_cases(method, axes), cases;
            for (std::size_t j = 0; j < all.size(); j += stride)
                cases.push_back(all[j]);
            ggxapp::StressMap map = ggxapp::device_stress_map(sampler, method, precision, cases, axes);
            std::uint64_t counted = 0, nan_inf = 0;
            for (const ggxapp::CellCounts& cell : map) {
                counted += cell.cases;
                nan_inf += cell.failures[ggxapp::nan_inf];
            }
            const std::string what = "stress " + label(method, precision);
            check(counted == cases.size(), what + ": cases counted");
            check(nan_inf == 0, what + ": " + std::to_string(nan_inf) + " NaN/Inf");
            std::cout << "ok " << what << " (" << cases.size() << " of " << all.size() << " cases)\n";
        }
}

} // namespace

int main(int argc, char** argv)
{
    const std::string usage = "usage: oclgrind_driver per-sample|pdf|furnace|world|user|stress [COUNT]";
    if (argc < 2 || argc > 3) {
        std::cerr << usage << "\n";
        return 2;
    }
    const std::string what = argv[1];
    const std::uint64_t count = argc == 3 ? std::strtoull(argv[2], nullptr, 10) : 1000;
    try {
        ggxcl::Sampler sampler;
        std::cout << "device: " << sampler.device_name() << "\n";
        if (what == "per-sample")
            run_per_sample(sampler, count);
        else if (what == "pdf")
            run_pdf(sampler, count);
        else if (what == "furnace")
            run_furnace(sampler, count);
        else if (what == "world")
            run_world(sampler, count);
        else if (what == "user")
            run_user(sampler, count);
        else if (what == "stress")
            run_stress(sampler, count);
        else {
            std::cerr << usage << "\n";
            return 2;
        }
    } catch (const std::exception& e) {
        std::cerr << "FAIL " << what << ": " << e.what() << "\n";
        return 1;
    }
    if (failures != 0)
        std::cerr << "FAIL " << what << ": " << failures << " failed checks\n";
    return failures == 0 ? 0 : 1;
}
