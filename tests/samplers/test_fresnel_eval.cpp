// test_fresnel_eval.cpp - ggx_fresnel.h and ggx_bsdf.h, as a user kernel
// includes them, against the double reference: the three Fresnel terms on
// grids of cosines and indices (total internal reflection and normal
// incidence exactly where they must be), the roughness conventions, and the
// BRDF value f |cos| for random pairs of directions, which divided by each
// method's pdf of a sampled o gives that sample's weight.
#include <doctest/doctest.h>

#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>

#include "device_fixture.hpp"

namespace {

using ggxref::Vec3;

// fresnel: one work-item per (c, eta, k, f0), four outputs (the last: alpha from f0 as a roughness, plus
// 1 where (f0, f0/2) is effectively smooth); eval: one per (i, o, ax, ay), f |cos|; dielectric: one
// per (i, o, ax, ay, eta, radiance), the transmission and the whole dielectric.
const char* fresnel_kernel = R"CL(
__kernel void fresnel(__global const float* in, __global float* out)
{
    uint g = get_global_id(0);
    __global const float* p = in + 4 * g;
    __global float* r = out + 4 * g;
    r[0] = ggx_fresnel_dielectric(p[0], p[1]);
    r[1] = ggx_fresnel_conductor(p[0], p[1], p[2]);
    r[2] = ggx_fresnel_schlick(p[0], p[3]);
    r[3] = ggx_alpha_from_perceptual_roughness(p[3]) + (float)ggx_is_effectively_smooth(p[3], 0.5f * p[3]);
}

__kernel void eval(__global const float* in, __global float* out)
{
    uint g = get_global_id(0);
    __global const float* p = in + 8 * g;
    out[g] = ggx_eval_reflection(ggx_vec3_make(p[0], p[1], p[2]), ggx_vec3_make(p[3], p[4], p[5]), p[6], p[7]);
}

__kernel void dielectric(__global const float* in, __global float* out)
{
    uint g = get_global_id(0);
    __global const float* p = in + 10 * g;
    ggx_vec3 i = ggx_vec3_make(p[0], p[1], p[2]), o = ggx_vec3_make(p[3], p[4], p[5]);
    out[2 * g] = ggx_eval_transmission(i, o, p[6], p[7], p[8], (int)p[9]);
    out[2 * g + 1] = ggx_eval_dielectric(i, o, p[6], p[7], p[8], (int)p[9]);
}
)CL";

std::vector<float> run(const char* kernel_name, const std::vector<float>& in, std::size_t items, std::size_t per_item)
{
    return ggxtest::run_user_kernel(fresnel_kernel, kernel_name, in, items, per_item);
}

struct FresnelCase {
    float c, eta, k, f0;
};

std::vector<FresnelCase> fresnel_cases()
{
    std::vector<FresnelCase> cases;
    const float etas[] = {1.0f / 1.5f, 1.0f / 1.33f, 1.001f, 1.33f, 1.5f, 2.42f};
    const float ks[] = {0.0f, 0.5f, 2.78f, 3.98f, 6.78f};
    for (int step = -200; step <= 200; ++step)
        for (float eta : etas)
            for (float k : ks)
                cases.push_back({float(step) / 200.0f, eta, k, float((step + 200) % 97) / 96.0f});
    return cases;
}

} // namespace

TEST_CASE("Fresnel terms and roughness conventions equal the reference")
{
    const std::vector<FresnelCase> cases = fresnel_cases();
    std::vector<float> in;
    for (const FresnelCase& f : cases)
        in.insert(in.end(), {f.c, f.eta, f.k, f.f0});
    const std::vector<float> r = run("fresnel", in, cases.size(), 4);
    std::size_t bad[4] = {}, tir = 0, tir_exact = 0;
    std::string failures;  // the inputs and both values of each case outside its bound
    const auto expect_close = [&](int term, float device, double reference, double relative, double absolute,
                                  const FresnelCase& f) {
        if (ggxtest::close_to(device, reference, relative, absolute))
            return;
        if (bad[term]++ >= 20)
            return;
        std::ostringstream line;
        line << std::setprecision(9) << (term == 0 ? "dielectric" : term == 1 ? "conductor" : "schlick") << ": c "
             << f.c << " eta " << f.eta << " k " << f.k << " f0 " << f.f0 << ": device " << device << ", reference "
             << reference << "\n";
        failures += line.str();
    };
    for (std::size_t j = 0; j < cases.size(); ++j) {
        const FresnelCase& f = cases[j];
        const double dielectric = ggxref::fresnel_dielectric(f.c, f.eta);
        expect_close(0, r[4 * j], dielectric, 2e-5, 2e-6, f);
        if (f.c >= 0.0f)
            expect_close(1, r[4 * j + 1], ggxref::fresnel_conductor(f.c, f.eta, f.k), 2e-5, 2e-6, f);
        expect_close(2, r[4 * j + 2], ggxref::fresnel_schlick(f.c, f.f0), 2e-6, 2e-6, f);
        const double alpha = double(f.f0) * f.f0;
        bad[3] += r[4 * j + 3] != float(alpha) + (f.f0 < 1e-3f ? 1.0f : 0.0f);
        if (dielectric == 1.0 && f.c != 0.0f) {  // total internal reflection: exactly 1 on the device too
            ++tir;
            tir_exact += r[4 * j] == 1.0f;
        }
        if (f.c == 1.0f || f.c == -1.0f) {  // normal incidence: ((eta - 1)/(eta + 1))^2 from either side
            const double r0 = std::pow((double(f.eta) - 1.0) / (double(f.eta) + 1.0), 2.0);
            CHECK(r[4 * j] == doctest::Approx(r0).epsilon(1e-5));
        }
    }
    const char* names[] = {"dielectric", "conductor", "schlick", "roughness"};
    CAPTURE(ggxtest::sampler().device_name());
    CAPTURE(failures);
    for (int q = 0; q < 4; ++q) {
        CAPTURE(std::string(names[q]));
        CHECK(bad[q] == 0);
    }
    CHECK(tir > 1000);
    CHECK(tir_exact == tir);
}

TEST_CASE("the BRDF value equals the reference, and over each method's pdf gives the weight")
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<float> in;
    std::vector<double> expected, separable;
    const std::size_t n = 4000;
    for (std::size_t j = 0; j < n; ++j) {
        auto direction = [&](double zmin) {
            const double z = zmin + (1.0 - zmin) * uniform(rng), s = std::sqrt(1 - z * z), a = 6.283185307 * uniform(rng);
            return Vec3{float(s * std::cos(a)), float(s * std::sin(a)), float(z)};
        };
        const Vec3 i = direction(j % 5 == 0 ? -0.5 : 0.02), o = direction(j % 7 == 0 ? -0.5 : 0.02);
        const double ax = float(std::exp(std::log(0.02) + std::log(100.0) * uniform(rng)));
        const double ay = j % 3 == 0 ? ax : double(float(std::exp(std::log(0.02) + std::log(100.0) * uniform(rng))));
        in.insert(in.end(), {float(i.x), float(i.y), float(i.z), float(o.x), float(o.y), float(o.z), float(ax), float(ay)});
        expected.push_back(ggxref::brdf_cos(i, o, ax, ay));
        const Vec3 h = ggxref::normalize(i + o);
        separable.push_back(i.z > 0 && o.z > 0 ? ggxref::D(h, ax, ay) * ggxref::G2_separable(i, o, ax, ay) / (4 * i.z)
                                               : 0.0);
    }
    const std::vector<float> r = run("eval", in, n, 1);
    std::size_t bad = 0, zero_ok = 0, below = 0, control = 0;
    for (std::size_t j = 0; j < n; ++j) {
        bad += !ggxtest::close_to(r[j], expected[j], 1e-4, 1e-7 * (1.0 + expected[j]));
        if (expected[j] == 0.0)
            ++below, zero_ok += r[j] == 0.0f;
        control += !ggxtest::close_to(r[j], separable[j], 1e-3, 1e-6);
    }
    CHECK(bad == 0);
    CHECK(below > 300);
    CHECK(zero_ok == below);
    CHECK(control > 1000);  // control: the comparison tells G2's height-correlated form from the separable one
}

TEST_CASE("every method's weight is the BRDF value over its pdf")
{
    std::size_t checked = 0;
    for (ggxcl::Method method : ggxcl::all_methods)
        for (auto [alpha, theta] : {std::pair{0.05f, 30.0}, {0.4f, 70.0}, {1.0f, 85.0}}) {
            ggxcl::SampleParams p;
            p.method = method;
            p.alpha_x = p.alpha_y = alpha;
            p.view = ggxcl::view_from_angles(theta, 20.0);
            const std::uint32_t n = 2048;
            ggxcl::SampleSet s = ggxtest::sampler().generate(p, {5, 0, n}, {ggxcl::Field::o, ggxcl::Field::pdf_o,
                                                                             ggxcl::Field::weight});
            std::vector<float> in;
            for (std::uint32_t j = 0; j < n; ++j)
                in.insert(in.end(), {p.view.x, p.view.y, p.view.z, s.o[j], s.o[n + j], s.o[2 * n + j], alpha,
                                     alpha});
            const std::vector<float> f = run("eval", in, n, 1);
            std::size_t bad = 0;
            for (std::uint32_t j = 0; j < n; ++j)
                if (s.weight[j] > 0.0f) {
                    ++checked;
                    bad += !ggxtest::close_to(f[j] / s.pdf_o[j], s.weight[j], 1e-3, 1e-6);
                }
            CAPTURE(std::string(ggxcl::method_name(method)));
            CAPTURE(alpha);
            CHECK(bad == 0);
        }
    CHECK(checked > 30000);
}

namespace {

// A direction with z in [zmin, zmax], float-exact.
Vec3 random_direction(std::mt19937_64& rng, double zmin, double zmax)
{
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double z = zmin + (zmax - zmin) * uniform(rng), s = std::sqrt(1 - z * z), a = 6.283185307 * uniform(rng);
    return {float(s * std::cos(a)), float(s * std::sin(a)), float(z)};
}

struct DielectricCase {
    Vec3 i, o;
    double ax, ay, eta;
    int radiance;
};

std::vector<float> device_dielectric(const std::vector<DielectricCase>& cases)
{
    std::vector<float> in;
    for (const DielectricCase& c : cases)
        in.insert(in.end(), {float(c.i.x), float(c.i.y), float(c.i.z), float(c.o.x), float(c.o.y), float(c.o.z),
                             float(c.ax), float(c.ay), float(c.eta), float(c.radiance)});
    return run("dielectric", in, cases.size(), 2);
}

// Refraction of i through m (i.m = c > 0), relative index eta; false at total internal reflection.
bool refract(const Vec3& i, const Vec3& m, double eta, Vec3& o)
{
    const double c = ggxref::dot(i, m), sin2 = (1.0 - c * c) / (eta * eta);
    if (sin2 >= 1.0)
        return false;
    o = (c / eta - std::sqrt(1.0 - sin2)) * m - (1.0 / eta) * i;
    return true;
}

} // namespace

TEST_CASE("the transmission and the whole dielectric equal the reference, from both sides")
{
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<DielectricCase> cases;
    const double etas[] = {1.5, 1.0 / 1.5, 1.33, 2.42};
    for (std::size_t j = 0; j < 8000; ++j) {
        const double ax = float(std::exp(std::log(0.03) + std::log(30.0) * uniform(rng)));
        const double ay = j % 2 ? ax : double(float(std::exp(std::log(0.03) + std::log(30.0) * uniform(rng))));
        const Vec3 i = random_direction(rng, j % 4 == 0 ? -0.98 : 0.02, j % 4 == 0 ? -0.02 : 0.98);
        const Vec3 o = random_direction(rng, -0.98, 0.98);
        cases.push_back({i, o, ax, ay, float(etas[j % 4]), int(j / 4 % 2)});
    }
    const std::vector<float> r = device_dielectric(cases);
    std::size_t bad_t = 0, bad_all = 0, transmitted = 0, reflected = 0;
    for (std::size_t j = 0; j < cases.size(); ++j) {
        const DielectricCase& c = cases[j];
        const double t = ggxref::btdf_cos(c.i, c.o, c.ax, c.ay, c.eta, c.radiance);
        const double all = ggxref::dielectric_cos(c.i, c.o, c.ax, c.ay, c.eta, c.radiance);
        bad_t += !ggxtest::close_to(r[2 * j], t, 2e-4, 1e-6 * (1.0 + t));
        bad_all += !ggxtest::close_to(r[2 * j + 1], all, 2e-4, 1e-6 * (1.0 + all));
        transmitted += t > 0.0;
        reflected += c.i.z * c.o.z > 0.0 && all > 0.0;
    }
    CHECK(bad_t == 0);
    CHECK(bad_all == 0);
    CHECK(transmitted > 500);
    CHECK(reflected > 1500);
}

TEST_CASE("a smooth dielectric reflects and transmits all it receives in importance transport")
{
    // E over VNDF normals m of [value(o_r) / pdf(o_r | m) + value(o_t) / pdf(o_t | m)], the densities
    // of the reflected and refracted directions given m (SPEC's Jacobians, without the lobe
    // choice): the reflectance plus the transmittance, near 1 for alpha 0.02 in importance
    // transport. Control: radiance transport scales the transmission by 1/eta^2 and misses it.
    const double alpha = 0.02;
    for (double eta : {1.5, 1.0 / 1.5})
        for (double theta : {30.0, 60.0}) {
            const Vec3 i{std::sin(theta * 0.0174532925), 0.0, std::cos(theta * 0.0174532925)};
            std::vector<DielectricCase> cases;
            std::vector<double> pdf_reflect, pdf_refract;
            std::mt19937_64 rng(23);
            std::uniform_real_distribution<double> uniform(0.0, 1.0);
            const ggxref::Params params{alpha, alpha, i};
            for (int j = 0; j < 20000; ++j) {
                const Vec3 m = ggxref::sample_normal(ggxref::Method::heitz, params, uniform(rng), uniform(rng));
                const double im = ggxref::dot(i, m), vndf = ggxref::vndf_pdf(m, i, alpha, alpha);
                const Vec3 o_r = 2.0 * im * m - i;
                Vec3 o_t{0, 0, 0};
                const bool refracts = refract(i, m, eta, o_t);
                for (int radiance : {0, 1}) {
                    cases.push_back({i, o_r, alpha, alpha, eta, radiance});
                    pdf_reflect.push_back(vndf / (4.0 * im));
                    cases.push_back({i, o_t, alpha, alpha, eta, radiance});
                    const double om = ggxref::dot(o_t, m);
                    pdf_refract.push_back(refracts ? vndf * eta * eta * std::fabs(om) / std::pow(im + eta * om, 2.0)
                                                   : 0.0);
                }
            }
            const std::vector<float> r = device_dielectric(cases);
            double total[2] = {0.0, 0.0}, transmitted = 0.0;
            for (std::size_t k = 0; k < cases.size(); k += 2) {
                const int radiance = cases[k].radiance;
                total[radiance] += r[2 * k + 1] / pdf_reflect[k / 2];
                if (pdf_refract[k / 2] > 0.0) {
                    total[radiance] += r[2 * (k + 1) + 1] / pdf_refract[k / 2];
                    transmitted += radiance ? 0.0 : r[2 * (k + 1) + 1] / pdf_refract[k / 2];
                }
            }
            const double n = double(cases.size()) / 4.0;
            CAPTURE(eta);
            CAPTURE(theta);
            CHECK(total[0] / n == doctest::Approx(1.0).epsilon(0.02));
            if (transmitted / n > 0.3)  // control, where light crosses (not under total internal reflection)
                CHECK(std::fabs(total[1] / n - 1.0) > 0.1);
            else
                CHECK(eta < 1.0);  // only a view from the denser side reflects (nearly) everything
        }
}


TEST_CASE("Sampler::eval gives the BRDF value in tangent and world space, and enqueue_eval the same")
{
    std::mt19937_64 rng(29);
    std::vector<ggxcl::Vec3> directions;
    std::vector<Vec3> exact;
    for (int j = 0; j < 3000; ++j) {
        const Vec3 o = random_direction(rng, -0.3, 0.999);
        directions.push_back({float(o.x), float(o.y), float(o.z)});
        exact.push_back(o);
    }
    auto& s = ggxtest::sampler();
    for (ggxcl::Method method : ggxcl::all_methods)
        for (bool world : {false, true}) {
            ggxcl::SampleParams p;
            p.method = method;
            p.alpha_x = p.alpha_y = 0.35f;
            p.view = ggxcl::view_from_angles(50.0, 30.0);
            p.world_space = world;
            // Tangent space for the tangent-space methods: z is the normal. Around another normal
            // (caps-iso, world space) the reference sees the directions in that normal's frame.
            const bool about_normal = world || method == ggxcl::Method::caps_iso;
            if (about_normal)
                p.normal = {0.0f, 0.0f, 1.0f};
            const std::vector<float> values = s.eval(p, directions);
            std::size_t bad = 0, nonzero = 0;
            const Vec3 i = {p.view.x, p.view.y, p.view.z};
            for (std::size_t j = 0; j < directions.size(); ++j) {
                const double expected = ggxref::brdf_cos(ggxref::normalize(i), exact[j], 0.35f, 0.35f);
                bad += !ggxtest::close_to(values[j], expected, 2e-4, 1e-6 * (1.0 + expected));
                nonzero += values[j] > 0.0f;
            }
            CAPTURE(std::string(ggxcl::method_name(method)));
            CAPTURE(world);
            CHECK(bad == 0);
            CHECK(nonzero > 1500);
            // The same through the caller's buffers (eval normalizes the directions first, these are
            // unit to float rounding: equal within that).
            std::vector<float> planar(3 * directions.size());
            for (std::size_t j = 0; j < directions.size(); ++j) {
                planar[j] = directions[j].x;
                planar[directions.size() + j] = directions[j].y;
                planar[2 * directions.size() + j] = directions[j].z;
            }
            cl::Buffer dirs(s.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, planar.size() * 4, planar.data());
            cl::Buffer out(s.context(), CL_MEM_WRITE_ONLY, directions.size() * 4);
            s.enqueue_eval(s.queue(), p, std::uint32_t(directions.size()), dirs, out).wait();
            std::vector<float> enqueued(directions.size());
            s.queue().enqueueReadBuffer(out, CL_TRUE, 0, enqueued.size() * 4, enqueued.data());
            std::size_t differ = 0;
            for (std::size_t j = 0; j < values.size(); ++j)
                differ += !ggxtest::close_to(enqueued[j], values[j], 1e-5, 1e-9);
            CHECK(differ == 0);
        }
    // The pdf and the value are different quantities: eval is not the pdf.
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::caps;
    p.alpha_x = p.alpha_y = 0.35f;
    p.view = ggxcl::view_from_angles(50.0, 30.0);
    CHECK(s.eval(p, directions) != s.pdf(p, directions));
}
