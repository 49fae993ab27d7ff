// bench_accuracy.cpp - numerical error against the reference, the
// variance of the albedo estimator over a small table, and a dielectric
// furnace's reflectance and transmittance against the reference.
#include "bench_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ggx_quadrature.hpp"
#include "reference_bridge.hpp"
#include "user_checks.hpp"

namespace ggxapp {

namespace {

ggxref::Vec3 as_double(const ggxcl::Vec3& v)
{
    return {v.x, v.y, v.z};
}

// The sampler of `who` (its method and user sampler) at one cell.
ggxcl::SampleParams params_of(const ggxcl::SampleParams& who, ggxcl::Precision precision, double alpha,
                              double cos_theta, ggxcl::Sequence sequence = ggxcl::Sequence::philox)
{
    ggxcl::SampleParams p;
    p.method = who.method;
    p.user_sampler = who.user_sampler;
    p.precision = precision;
    p.sequence = sequence;
    p.alpha_x = p.alpha_y = float(alpha);
    p.view = ggxcl::view_from_angles(std::acos(cos_theta) * 180.0 / 3.14159265358979323846, 0.0);
    return ggxcl::normalized(p);
}

void add_errors(const ggxcl::SampleSet& d, ggxcl::Method method, const ggxref::Params& ref,
                std::vector<double>& angles, std::vector<double>& pdfs, std::uint64_t& non_finite)
{
    ggxref::Method ref_method = ggxbridge::reference_method(method);
    for (std::size_t j = 0; j < d.count; ++j) {
        ggxref::Sample r = ggxref::sample(ref_method, ref, d.u[j], d.u[d.count + j]);  // the device's own uniforms
        double angle = std::max(angle_between(as_double(d.m_at(j)), r.m), angle_between(as_double(d.o_at(j)), r.o));
        if (!std::isfinite(angle) || !std::isfinite(d.pdf_m[j]) || !std::isfinite(d.pdf_o[j])) {
            ++non_finite;
            continue;
        }
        angles.push_back(angle);
        pdfs.push_back(relative_error(d.pdf_m[j], r.pdf_m));
        // pdf_o of NDF normals divides by o.m: left out where that is ill-conditioned.
        if (ggxcl::method_traits(method).normals != ggxcl::Distribution::ndf || std::fabs(ggxref::dot(r.o, r.m)) >= 1e-2)
            pdfs.push_back(relative_error(d.pdf_o[j], r.pdf_o));
    }
}

// The mean of `values` and its standard error, from their spread.
void mean_and_error(const std::vector<double>& values, double& mean, double& standard_error)
{
    const double k = double(values.size());
    double sum = 0.0, squares = 0.0;
    for (double v : values)
        sum += v;
    mean = sum / k;
    for (double v : values)
        squares += (v - mean) * (v - mean);
    standard_error = std::sqrt(squares / (k - 1.0) / k);
}

} // namespace

void percentiles(std::vector<double>& errors, double& p99, double& max)
{
    if (errors.empty())
        return;
    max = *std::max_element(errors.begin(), errors.end());
    std::size_t k = std::size_t(0.99 * double(errors.size() - 1));
    std::nth_element(errors.begin(), errors.begin() + k, errors.end());
    p99 = errors[k];
}

double angle_between(const ggxref::Vec3& a, const ggxref::Vec3& b)
{
    return std::atan2(ggxref::length(ggxref::cross(a, b)), ggxref::dot(a, b));
}

double relative_error(double value, double reference)
{
    return reference == 0.0 ? std::fabs(value) : std::fabs(value - reference) / std::fabs(reference);
}

std::vector<ggxcl::SampleParams> accuracy_configs(ggxcl::Method method, ggxcl::Precision precision)
{
    ggxcl::SampleParams who;
    who.method = method;
    return accuracy_configs(who, precision);
}

std::vector<ggxcl::SampleParams> accuracy_configs(const ggxcl::SampleParams& who, ggxcl::Precision precision)
{
    std::vector<ggxcl::SampleParams> configs;
    for (double alpha : {0.05, 0.3, 1.0})
        for (double theta : {0.0, 45.0, 80.0})
            configs.push_back(params_of(who, precision, alpha, std::cos(theta * 3.14159265358979323846 / 180)));
    return configs;
}

NumericalError numerical_error(ggxcl::Backend& sampler, const ggxcl::SampleParams& who, ggxcl::Method method,
                               ggxcl::Precision precision, ggxcl::Sequence sequence)
{
    std::vector<double> angles, pdfs;
    NumericalError error;
    for (ggxcl::SampleParams p : accuracy_configs(who, precision)) {
        p.sequence = sequence;
        ggxcl::SampleSet d = sampler.generate(p, {accuracy_seed, 0, accuracy_samples},
                                              {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_m,
                                               ggxcl::Field::pdf_o, ggxcl::Field::u});
        add_errors(d, method, ggxbridge::reference_params(p), angles, pdfs, error.non_finite);
    }
    percentiles(angles, error.angle_p99, error.angle_max);
    percentiles(pdfs, error.pdf_p99, error.pdf_max);
    return error;
}

double pdf_disagreement(ggxcl::Backend& sampler, const ggxcl::SampleParams& who)
{
    double disagree = 0.0, with_density = 0.0;
    for (const ggxcl::SampleParams& p : accuracy_configs(who, who.precision))
        for (const PdfAgreement& a : pdf_agreements(sampler, p, {accuracy_seed, 0, accuracy_samples}, nullptr)) {
            disagree += double(a.failures());  // a pdf not finite or not positive on a kept sample counts
            with_density += double(a.with_density + a.not_finite + a.not_positive);
        }
    return with_density > 0.0 ? disagree / with_density : 1.0;
}

SceneVariance albedo_scene_variance(ggxcl::Backend& sampler, const ggxcl::SampleParams& who,
                                    ggxcl::Precision precision, int size, std::uint64_t samples_per_cell)
{
    SceneVariance scene;
    std::uint64_t seed = 1000;
    for (int a = 0; a < size; ++a)
        for (int v = 0; v < size; ++v) {
            ggxcl::SampleParams p = params_of(who, precision, (a + 0.5) / size, (v + 0.5) / size);
            ggxcl::FurnaceSums sums = sampler.furnace(p, {++seed, 0, samples_per_cell});
            scene.variance += sums.variance();
            scene.mean_albedo += sums.mean();
        }
    scene.variance /= double(size) * size;
    scene.mean_albedo /= double(size) * size;
    return scene;
}

std::vector<double> albedo_table(int size)
{
    std::vector<double> exact;
    for (int a = 0; a < size; ++a)
        for (int v = 0; v < size; ++v)
            exact.push_back(ggxref::albedo(ggxbridge::reference_params(
                params_of(ggxcl::SampleParams(), ggxcl::Precision::precise, (a + 0.5) / size, (v + 0.5) / size))));
    return exact;
}

double albedo_table_rmse(ggxcl::Backend& sampler, const ggxcl::SampleParams& who, ggxcl::Precision precision,
                         ggxcl::Sequence sequence, int size, std::uint64_t samples_per_cell, int streams,
                         const std::vector<double>& exact)
{
    double squared = 0.0;
    std::uint64_t seed = 5000;
    for (int a = 0; a < size; ++a)
        for (int v = 0; v < size; ++v) {
            ggxcl::SampleParams p = params_of(who, precision, (a + 0.5) / size, (v + 0.5) / size, sequence);
            for (int s = 0; s < streams; ++s) {
                const double e = sampler.furnace(p, {++seed, 0, samples_per_cell}).mean() - exact[a * size + v];
                squared += e * e;
            }
        }
    return std::sqrt(squared / (double(size) * size * streams));
}

ggxref::DielectricAlbedo dielectric_exact(const ggxcl::SampleParams& params)
{
    return ggxref::dielectric_albedo(ggxbridge::reference_params(ggxcl::normalized(params)), params.eta,
                                     params.transport == ggxcl::Transport::radiance);
}

DielectricAccuracy dielectric_accuracy(ggxcl::Backend& sampler, const ggxcl::SampleParams& params,
                                       const ggxref::DielectricAlbedo& exact)
{
    DielectricAccuracy a;
    a.exact_reflectance = exact.reflectance;
    a.exact_transmittance = exact.transmittance;
    std::vector<double> reflectances, transmittances;
    for (int s = 0; s < dielectric_streams; ++s) {
        const ggxcl::FurnaceSums sums = sampler.furnace(params, {9000u + std::uint64_t(s), 0, dielectric_stream_samples});
        reflectances.push_back(sums.reflectance());
        transmittances.push_back(sums.transmittance());
    }
    mean_and_error(reflectances, a.reflectance, a.reflectance_se);
    mean_and_error(transmittances, a.transmittance, a.transmittance_se);
    a.samples = dielectric_streams * dielectric_stream_samples;
    a.measured = true;
    return a;
}

} // namespace ggxapp
