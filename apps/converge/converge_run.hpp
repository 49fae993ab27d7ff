// converge_run.hpp - the measurements of `ggx converge`: for every method,
// sequence, configuration and integrand, the RMSE against the reference's
// exact value of the estimate from the first N samples of R independent
// streams (seeds), for N = 2^min .. 2^max, and the slope of log RMSE
// against log N; and each method's speed with each sequence (the fused
// estimator's ns per sample, timed as `ggx bench` times it).
#pragma once

#include <cstdint>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "converge_plan.hpp"

namespace ggxapp {

struct ConvergeCurve {
    SamplerChoice method;
    ggxcl::Sequence sequence;
    Integrand integrand;
    ConvergeConfig config;
    double reference = 0;               // the exact integral (double-precision quadrature)
    std::vector<std::uint64_t> counts;  // N = 2^min .. 2^max
    std::vector<double> rmse;           // over the R streams, against `reference`
    std::vector<double> mean;           // the mean of the R estimates
    double slope = 0;                   // least-squares slope of log RMSE against log N
};

// Every curve of the plan, in the order method, sequence, configuration,
// integrand, drawn on `sampler`'s device.
std::vector<ConvergeCurve> measure_convergence(ggxcl::Backend& sampler, const ConvergePlan& plan);

// Least-squares slope of log(y) against log(x) (positive x, y).
double log_log_slope(const std::vector<std::uint64_t>& x, const std::vector<double>& y);

struct ConvergeSpeed {
    SamplerChoice method;
    ggxcl::Sequence sequence;
    double ns_per_sample = 0;  // median of interleaved timed runs of the fused estimator
};
// One speed per method and sequence at the plan's first configuration (empty
// when the plan times nothing): the median of 5 wall-clock runs of
// Backend::furnace (the whole call, as a user makes it), the methods
// interleaved round by round so that the machine's drift spreads alike.
std::vector<ConvergeSpeed> measure_speeds(ggxcl::Backend& sampler, const ConvergePlan& plan);

} // namespace ggxapp
