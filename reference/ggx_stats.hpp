// ggx_stats.hpp - histograms of sampled directions and the chi-square tests that compare them
// with reference bin probabilities (goodness of fit) or with each other (homogeneity).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ggxref {

// Same binning as bin_probabilities: z in [-1, 1] into nz, phi = atan2(y, x) wrapped to [0, 2 pi)
// into nphi; index = iz_bin * nphi + iphi_bin. z is clamped to [-1, 1]; directions with a
// non-finite component are not counted (the histogram then sums to less than count).
std::vector<uint64_t> histogram_directions(const float* x, const float* y, const float* z, size_t count, int nz,
                                           int nphi);

struct ChiSquare {
    double statistic;
    int dof;         // bins used - 1
    double p_value;  // P(chi2_dof >= statistic); 0 without evidence: no samples, no degree of freedom,
                     // a probability or a statistic that is not finite
    int bins_used;
};

// Observed counts against N p (p normalized to sum 1). Bins expecting fewer than 5 are pooled, a
// pool still under 5 is merged into the smallest kept bin; counts in bins of probability 0 form
// their own bin with expectation 1e-9, which makes the test reject.
// A probability that is not finite gives statistic NaN, dof 0, p 0.
ChiSquare chi_square_gof(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities);
// The same with each probability known within +- errors[k] (a quadrature's error estimate): a cell's
// term is (O - E)^2 / (E + (N error)^2), the expectation's own uncertainty added to the count's
// Poisson variance (errors of pooled bins add up); an empty `errors` is the plain test.
ChiSquare chi_square_gof(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities,
                         const std::vector<double>& errors);
// The same for float samples whose support edge coincides with a bin edge (the horizon, for bounded at
// alpha = 1): a direction within rounding of the edge may land on its far side. Up to 2 + 1e-6 N counts
// in bins of probability 0 are left out of the fit; more make the test reject as above.
ChiSquare chi_square_gof_float(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities,
                               const std::vector<double>& errors = {});
// Two histograms from the same distribution? Bins with a combined count under 10 are pooled the same way.
ChiSquare chi_square_homogeneity(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b);
// Per-test level for `tests` independent tests at family level alpha: 1 - (1 - alpha)^(1/tests).
double sidak_level(double alpha, int tests);

}  // namespace ggxref
