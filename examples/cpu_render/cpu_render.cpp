// cpu_render.cpp - the inner loop of a CPU renderer shading one GGX surface point with
// multiple importance sampling, calling ggxcl's device headers directly as plain C++ (no
// OpenCL): the reflected radiance of a disk light (radiance 1, angular radius 10 degrees, 35
// degrees from the normal) seen from a view at 60 degrees, roughness 0.3, Fresnel 1.
//
// Two strategies, combined by the balance heuristic (Veach 1997):
//   BSDF sampling  - ggx_sample_caps(i, ...) gives o, its pdf and the weight f cos / pdf;
//   light sampling - o uniform in the light's cone; f cos from ggx_eval_reflection (ggx_bsdf.h),
//                    the BSDF's pdf of that o from ggx_pdf_caps(i, o, ...).
// Each alone is unbiased too: the program prints the three estimates with their standard errors
// and exits with status 1 when the MIS estimate and either single strategy disagree by more than
// 5 standard errors (a wrong pdf would make them disagree).
//
// Build: c++ -std=c++17 -O2 -I<prefix>/include/ggxcl/cl cpu_render.cpp -o cpu_render
// (or find_package(ggxcl CONFIG COMPONENTS device_headers) and ggxcl::device_headers).
// Usage: cpu_render [samples = 1000000]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>

#include "ggx_philox.h"
#include "ggx_samplers.h"

namespace {

constexpr float pi = 3.14159265358979f;

struct Light {
    ggx_vec3 axis;  // unit direction to the light's centre, tangent space
    float cos_radius;
    float pdf() const { return 1.0f / (2.0f * pi * (1.0f - cos_radius)); }  // uniform over its cone
    bool contains(ggx_vec3 o) const { return ggx_dot(o, axis) >= cos_radius; }
};

// A direction uniform in the light's cone from two uniforms (about axis, via a basis).
ggx_vec3 sample_light(const Light& light, float u1, float u2)
{
    const float cos_t = 1.0f - u1 * (1.0f - light.cos_radius), sin_t = std::sqrt(1.0f - cos_t * cos_t);
    const float phi = 2.0f * pi * u2;
    const ggx_vec3 t = ggx_normalize(ggx_cross(ggx_vec3_make(0.0f, 1.0f, 0.0f), light.axis));
    const ggx_vec3 b = ggx_cross(light.axis, t);
    return ggx_add(ggx_add(ggx_scale(t, sin_t * std::cos(phi)), ggx_scale(b, sin_t * std::sin(phi))),
                   ggx_scale(light.axis, cos_t));
}

struct Estimate {
    double sum = 0, sum2 = 0;
    void add(double x) { sum += x, sum2 += x * x; }
    double mean(long n) const { return sum / double(n); }
    double error(long n) const { return std::sqrt(std::fmax(0.0, sum2 / double(n) - mean(n) * mean(n)) / double(n)); }
};

}  // namespace

int main(int argc, char** argv)
{
    const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
    if (n < 1000) {
        std::fprintf(stderr, "cpu_render: samples '%s': a whole number of at least 1000\n", argv[1]);
        return 2;
    }
    const float alpha = 0.3f, view = 60.0f * pi / 180.0f, tilt = 35.0f * pi / 180.0f;
    const ggx_vec3 i = ggx_vec3_make(std::sin(view), 0.0f, std::cos(view));
    const Light light{ggx_vec3_make(-std::sin(tilt), 0.0f, std::cos(tilt)), std::cos(10.0f * pi / 180.0f)};
    Estimate bsdf_only, light_only, mis;
    for (long k = 0; k < n; ++k) {
        float u1, u2, v1, v2;
        ggx_uniforms(1, 2 * std::uint64_t(k), &u1, &u2);
        ggx_uniforms(1, 2 * std::uint64_t(k) + 1, &v1, &v2);
        // BSDF sampling: the sampler's weight is f cos / pdf; the light's pdf of o for MIS.
        const ggx_sample s = ggx_sample_caps(i, alpha, alpha, u1, u2);
        const bool hit = s.pdf_o > 0.0f && light.contains(s.o);
        bsdf_only.add(hit ? s.weight : 0.0);
        const double w_bsdf = hit ? s.pdf_o / (s.pdf_o + light.pdf()) : 0.0;
        // Light sampling: f cos / pdf_light; the BSDF's pdf of o for MIS.
        const ggx_vec3 o = sample_light(light, v1, v2);
        const float f_cos = ggx_eval_reflection(i, o, alpha, alpha), pdf_bsdf = ggx_pdf_caps(i, o, alpha, alpha);
        light_only.add(f_cos / light.pdf());
        const double w_light = light.pdf() / (light.pdf() + pdf_bsdf);
        mis.add(w_bsdf * s.weight + w_light * f_cos / light.pdf());
    }
    std::printf("reflected radiance, %ld samples each:\n", n);
    std::printf("  BSDF sampling (caps)  %.6f +- %.6f\n", bsdf_only.mean(n), bsdf_only.error(n));
    std::printf("  light sampling        %.6f +- %.6f\n", light_only.mean(n), light_only.error(n));
    std::printf("  MIS, balance          %.6f +- %.6f\n", mis.mean(n), mis.error(n));
    for (const Estimate* single : {&bsdf_only, &light_only}) {
        const double sigma = std::hypot(single->error(n), mis.error(n));
        if (!(std::fabs(single->mean(n) - mis.mean(n)) <= 5.0 * sigma)) {
            std::printf("the estimates disagree by more than 5 standard errors\n");
            return 1;
        }
    }
    return 0;
}
