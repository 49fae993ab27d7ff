// sample_compare.hpp - device samples against reference samples drawn from
// the same uniforms, sample by sample: angle of m and o, relative error of
// pdf_m and pdf_o, absolute error of the weight, with the two-level bounds of
// docs/TESTING.md (99.9% of the samples / the worst sample).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "device_fixture.hpp"
#include "error_bounds.hpp"

namespace ggxtest {

constexpr ErrorBound angle_bound{"angle of m and o (rad)", 2e-5, 2e-3};
constexpr ErrorBound pdf_bound{"relative error of pdf_m and pdf_o", 2e-4, 1e-2};
constexpr ErrorBound weight_bound{"absolute error of weight", 2e-5, 2e-3};

struct SampleErrors {
    std::vector<double> angle, pdf, weight;
    std::size_t non_finite = 0;
    double worst_angle = 0;
    std::string worst_where;
};

double angle_between(const ggxref::Vec3& a, const ggxref::Vec3& b);

// The reference sample j for the uniforms (u1, u2).
using ReferenceSampler = std::function<ggxref::Sample(std::size_t j, double u1, double u2)>;

// Compares every sample of `device` (all fields, sample j from the uniforms of
// (seed, j) in `sequence`) with `reference`.  For ndf, pdf_o = pdf_m / (4 |i.m|) is compared
// only where |i.m| = |o.m| >= 1e-2: below it float cancellation in i.m exceeds the bound.
void compare_samples(const ggxcl::SampleSet& device, std::uint64_t seed, const ReferenceSampler& reference,
                     bool is_ndf, const std::string& label, SampleErrors& errors,
                     ggxcl::Sequence sequence = ggxcl::Sequence::philox);

// No NaN/Inf and every error within its bounds.
void check_sample_errors(const std::string& name, const SampleErrors& errors,
                         const ErrorBound& angle = angle_bound, const ErrorBound& pdf = pdf_bound,
                         const ErrorBound& weight = weight_bound);

} // namespace ggxtest
