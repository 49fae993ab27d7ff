// converge_run.cpp - drawing the streams and forming the errors of `ggx converge`.
#include "converge_run.hpp"

#include <cmath>

#include "bench_speed.hpp"
#include "reference_bridge.hpp"

namespace ggxapp {

namespace {

// Squared errors and estimates, summed over streams, per count; and the
// running sum of the stream being drawn.
struct Accumulator {
    std::vector<double> squared_error, estimate;
    double stream_total = 0.0;
};

// Adds a chunk of one stream (its samples from `offset` on) to the running
// sums, one per integrand, and the estimate of each count 2^k the chunk
// completes to its accumulator.
void add_chunk(const ggxcl::SampleView& s, std::uint64_t offset, const ConvergePlan& plan,
               const std::vector<ggxref::Light>& lights, const std::vector<double>& references,
               std::vector<Accumulator>& sums)
{
    for (std::size_t i = 0; i < lights.size(); ++i) {
        Accumulator& a = sums[i];
        for (std::uint64_t j = 0; j < s.count; ++j) {
            const double w = s.weight[j];
            if (w != 0.0)
                a.stream_total += w * ggxref::light_value(lights[i], {s.o[j], s.o[s.stride + j], s.o[2 * s.stride + j]});
            const std::uint64_t n = offset + j + 1;
            if ((n & (n - 1)) == 0 && n >= (std::uint64_t(1) << plan.min_exponent)) {  // n = 2^k
                const std::size_t k = std::size_t(std::log2(double(n))) - std::size_t(plan.min_exponent);
                const double e = a.stream_total / double(n);
                a.squared_error[k] += (e - references[i]) * (e - references[i]);
                a.estimate[k] += e;
            }
        }
    }
}

// The curves of one method, sequence and configuration: R streams of 2^max samples.
std::vector<ConvergeCurve> measure_cell(ggxcl::Backend& sampler, const ConvergePlan& plan, const SamplerChoice& method,
                                        ggxcl::Sequence sequence, const ConvergeConfig& config)
{
    const ggxcl::SampleParams p = converge_params(method, sequence, config, plan.precision);
    const ggxref::Params r = ggxbridge::reference_params(p);
    const std::size_t counts = std::size_t(plan.max_exponent - plan.min_exponent + 1);
    std::vector<ggxref::Light> lights;
    std::vector<double> references;
    std::vector<Accumulator> sums(plan.integrands.size(), Accumulator{std::vector<double>(counts), std::vector<double>(counts), 0.0});
    for (Integrand integrand : plan.integrands) {
        lights.push_back(light_of(integrand, config.theta));
        references.push_back(ggxref::reflected_radiance(r, lights.back()));
    }
    const std::uint64_t n = std::uint64_t(1) << plan.max_exponent;
    for (int stream = 0; stream < plan.randomizations; ++stream) {
        for (Accumulator& a : sums)
            a.stream_total = 0.0;
        sampler.generate_chunk_views(p, {plan.seed + std::uint64_t(stream), 0, n}, {ggxcl::Field::o, ggxcl::Field::weight},
                                     [&](const ggxcl::SampleView& view, std::uint64_t offset) {
                                         add_chunk(view, offset, plan, lights, references, sums);
                                     });
    }
    std::vector<ConvergeCurve> curves;
    for (std::size_t i = 0; i < plan.integrands.size(); ++i) {
        ConvergeCurve c{method, sequence, plan.integrands[i], config, references[i], {}, {}, {}, 0.0};
        for (std::size_t k = 0; k < counts; ++k) {
            c.counts.push_back(std::uint64_t(1) << (plan.min_exponent + int(k)));
            c.rmse.push_back(std::sqrt(sums[i].squared_error[k] / plan.randomizations));
            c.mean.push_back(sums[i].estimate[k] / plan.randomizations);
        }
        c.slope = log_log_slope(c.counts, c.rmse);
        curves.push_back(std::move(c));
    }
    return curves;
}

} // namespace

double log_log_slope(const std::vector<std::uint64_t>& x, const std::vector<double>& y)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double lx = std::log(double(x[k])), ly = std::log(y[k]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::vector<ConvergeCurve> measure_convergence(ggxcl::Backend& sampler, const ConvergePlan& plan)
{
    sampler.set_chunk_size(std::uint64_t(1) << plan.max_exponent);  // a stream in one chunk
    std::vector<ConvergeCurve> curves;
    for (const SamplerChoice& method : plan.methods)
        for (ggxcl::Sequence sequence : plan.sequences)
            for (const ConvergeConfig& config : plan.configs)
                for (ConvergeCurve& c : measure_cell(sampler, plan, method, sequence, config))
                    curves.push_back(std::move(c));
    return curves;
}

std::vector<ConvergeSpeed> measure_speeds(ggxcl::Backend& sampler, const ConvergePlan& plan)
{
    if (plan.speed_count == 0)
        return {};
    std::vector<ConvergeSpeed> speeds;
    std::vector<ggxcl::SampleParams> params;
    for (const SamplerChoice& method : plan.methods)
        for (ggxcl::Sequence sequence : plan.sequences) {
            params.push_back(converge_params(method, sequence, plan.configs.front(), plan.precision));
            speeds.push_back({method, sequence, 0.0});
            sampler.furnace(params.back(), {1, 0, 1024});  // builds the program
        }
    std::vector<std::vector<double>> ns(params.size());
    for (int round = 0; round < 5; ++round)
        for (std::size_t t = 0; t < params.size(); ++t)
            ns[t].push_back(
                wall_ns_per_sample([&] { sampler.furnace(params[t], {1, 0, plan.speed_count}); }, plan.speed_count));
    for (std::size_t t = 0; t < params.size(); ++t)
        speeds[t].ns_per_sample = summarize(ns[t]).median;
    return speeds;
}

} // namespace ggxapp
