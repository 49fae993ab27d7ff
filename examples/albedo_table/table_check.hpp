// table_check.hpp - the Monte Carlo table against the quadrature.  Cell c's
// estimate is the mean of its n weights; it passes when
//   |mean - E| <= z_limit * sigma / sqrt(n) + float_allowance,
// sigma^2 = max(sample variance, E (1 - E)) with E the quadrature value.
// E (1 - E) is the largest variance a weight in [0, 1] with mean E can have
// (Bhatia-Davis): it covers the rare samples that carry the whole deficit
// of a near-mirror cell (a reflection below the horizon, weight 0; with
// 1 - E = 3e-4, n = 8192 expects two and often draws none, and the sample
// variance is then nearly 0).  ndf's weights can exceed 1: its sample
// variance then decides.  z_limit = 5: a normal deviate beyond 5 has
// probability 6e-7, so all 6144 cells pass by chance with probability
// > 0.996 (the seed is fixed: the outcome is reproducible).
// float_allowance = 2e-5: one weight in float is within 2e-5 of its double
// value (docs/TESTING.md); block sums of 64 floats add at most 64 x 6e-8
// relative.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device_albedo.hpp"

namespace albedo {

constexpr double z_limit = 5.0;
constexpr double float_allowance = 2e-5;

struct CellEstimate {
    double mean = 0.0, variance = 0.0;  // of the weights
    std::uint64_t samples = 0;
};

std::vector<CellEstimate> estimates(const CellSums& sums, std::uint64_t samples_per_cell);

struct CheckResult {
    int failures = 0;            // cells beyond the tolerance
    double max_abs_error = 0.0;  // largest |mean - E|
    double max_z = 0.0;          // largest |mean - E| / (sigma / sqrt(n))
    std::string worst;           // the cell of the largest ratio to its tolerance
};

CheckResult check_table(const std::vector<CellEstimate>& table, const std::vector<double>& quadrature);

std::vector<float> means_of(const std::vector<CellEstimate>& table);

} // namespace albedo
