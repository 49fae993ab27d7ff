// table_check.cpp - estimates, their standard errors and the comparison
// with the quadrature.
#include "table_check.hpp"

#include <cmath>
#include <sstream>

namespace albedo {

std::vector<CellEstimate> estimates(const CellSums& sums, std::uint64_t samples_per_cell)
{
    const double n = double(samples_per_cell);
    std::vector<CellEstimate> table(sums.sum.size());
    for (std::size_t c = 0; c < table.size(); ++c) {
        const double mean = sums.sum[c] / n;
        const double variance = std::fmax(0.0, (sums.sum_of_squares[c] - n * mean * mean) / (n - 1.0));
        table[c] = {mean, variance, samples_per_cell};
    }
    return table;
}

namespace {

// sigma / sqrt(n) of table_check.hpp for a cell whose quadrature value is e.
double standard_error(const CellEstimate& cell, double e)
{
    const double bound = std::fmax(0.0, e * (1.0 - e));
    return std::sqrt(std::fmax(cell.variance, bound) / double(cell.samples));
}

std::string describe(std::size_t c, const CellEstimate& cell, double e, double standard_error)
{
    std::ostringstream out;
    out << "row " << c / table_size << " column " << c % table_size << ": " << cell.mean << " vs " << e
        << " (standard error " << standard_error << ")";
    return out.str();
}

} // namespace

CheckResult check_table(const std::vector<CellEstimate>& table, const std::vector<double>& quadrature)
{
    CheckResult result;
    double worst_ratio = -1.0;
    for (std::size_t c = 0; c < table.size(); ++c) {
        const double error = std::fabs(table[c].mean - quadrature[c]);
        const double se = standard_error(table[c], quadrature[c]);
        const double tolerance = z_limit * se + float_allowance;
        result.max_abs_error = std::fmax(result.max_abs_error, error);
        result.max_z = std::fmax(result.max_z, se > 0.0 ? error / se : 0.0);
        result.failures += error > tolerance ? 1 : 0;
        if (error / tolerance > worst_ratio) {
            worst_ratio = error / tolerance;
            result.worst = describe(c, table[c], quadrature[c], se);
        }
    }
    return result;
}

std::vector<float> means_of(const std::vector<CellEstimate>& table)
{
    std::vector<float> means;
    for (const CellEstimate& cell : table)
        means.push_back(float(cell.mean));
    return means;
}

} // namespace albedo
