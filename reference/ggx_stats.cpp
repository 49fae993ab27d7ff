// ggx_stats.cpp - direction histograms, chi-square goodness of fit and homogeneity with pooling of
// sparse bins, and the Sidak per-test level.
#include "ggx_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/distributions/chi_squared.hpp>

namespace ggxref {
namespace {

constexpr double pi = 3.14159265358979323846;

// A bin after pooling: observed counts (one or two samples) and their expectations.
struct Cell {
    double observed[2], expected[2];
    double size;  // the quantity pooling looks at: expected count (gof) or combined count (homogeneity)
    double error = 0.0;  // the expected count's own uncertainty (gof with quadrature errors)
};

void add(Cell& to, const Cell& c)
{
    for (int s = 0; s < 2; ++s) {
        to.observed[s] += c.observed[s];
        to.expected[s] += c.expected[s];
    }
    to.size += c.size;
    to.error += c.error;
}

// Cells with size < min_size are pooled; a pool still under min_size joins the smallest kept cell.
std::vector<Cell> pool(const std::vector<Cell>& cells, double min_size)
{
    std::vector<Cell> kept;
    Cell pooled{{0.0, 0.0}, {0.0, 0.0}, 0.0};
    for (const Cell& c : cells) {
        if (c.size >= min_size)
            kept.push_back(c);
        else
            add(pooled, c);
    }
    if (pooled.size <= 0.0)
        return kept;
    if (pooled.size >= min_size || kept.empty()) {
        kept.push_back(pooled);
    } else {
        auto by_size = [](const Cell& x, const Cell& y) { return x.size < y.size; };
        add(*std::min_element(kept.begin(), kept.end(), by_size), pooled);
    }
    return kept;
}

ChiSquare finish(const std::vector<Cell>& cells, int samples)
{
    ChiSquare r{0.0, int(cells.size()) - 1, 0.0, int(cells.size())};
    for (const Cell& c : cells)
        for (int s = 0; s < samples; ++s) {
            const double d = c.observed[s] - c.expected[s];
            if (c.expected[s] > 0.0)
                r.statistic += d * d / (c.expected[s] + c.error * c.error);
        }
    // No degree of freedom, or a statistic that is not finite, is no evidence: p stays 0.
    if (r.dof > 0 && std::isfinite(r.statistic))
        r.p_value = boost::math::cdf(boost::math::complement(boost::math::chi_squared(r.dof), r.statistic));
    return r;
}

}  // namespace

std::vector<uint64_t> histogram_directions(const float* x, const float* y, const float* z, size_t count, int nz,
                                           int nphi)
{
    std::vector<uint64_t> h(size_t(nz) * size_t(nphi), 0);
    for (size_t k = 0; k < count; ++k) {
        if (!std::isfinite(x[k]) || !std::isfinite(y[k]) || !std::isfinite(z[k]))
            continue;
        const double zc = std::clamp(double(z[k]), -1.0, 1.0);
        double phi = std::atan2(double(y[k]), double(x[k]));
        if (phi < 0.0)
            phi += 2.0 * pi;
        const int jz = std::min(nz - 1, int((zc + 1.0) * 0.5 * nz));
        const int jp = std::min(nphi - 1, int(phi / (2.0 * pi) * nphi));
        ++h[size_t(jz) * nphi + jp];
    }
    return h;
}

ChiSquare chi_square_gof(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities)
{
    return chi_square_gof(observed, probabilities, {});
}

ChiSquare chi_square_gof(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities,
                         const std::vector<double>& errors)
{
    double n = 0.0, total_p = 0.0, impossible = 0.0;
    for (size_t k = 0; k < observed.size(); ++k) {
        if (!std::isfinite(probabilities[k]))
            return {std::numeric_limits<double>::quiet_NaN(), 0, 0.0, 0};
        n += double(observed[k]);
        total_p += probabilities[k];
    }
    if (n == 0.0 || total_p <= 0.0)
        return {0.0, 0, 0.0, 0};
    std::vector<Cell> cells;
    for (size_t k = 0; k < observed.size(); ++k) {
        if (probabilities[k] > 0.0) {
            const double e = n * probabilities[k] / total_p;
            const double error = errors.empty() ? 0.0 : n * errors[k] / total_p;
            cells.push_back({{double(observed[k]), 0}, {e, 0}, e, error});
        } else {
            impossible += double(observed[k]);
        }
    }
    cells = pool(cells, 5.0);
    if (impossible > 0.0)
        cells.push_back({{impossible, 0}, {1e-9, 0}, 1e-9, 0.0});
    return finish(cells, 1);
}

ChiSquare chi_square_gof_float(const std::vector<uint64_t>& observed, const std::vector<double>& probabilities,
                               const std::vector<double>& errors)
{
    double n = 0.0, impossible = 0.0;
    for (size_t k = 0; k < observed.size(); ++k) {
        n += double(observed[k]);
        impossible += probabilities[k] > 0.0 ? 0.0 : double(observed[k]);
    }
    if (impossible > 2.0 + 1e-6 * n)
        return chi_square_gof(observed, probabilities, errors);
    std::vector<uint64_t> kept = observed;
    for (size_t k = 0; k < kept.size(); ++k)
        kept[k] = probabilities[k] > 0.0 ? kept[k] : 0;
    return chi_square_gof(kept, probabilities, errors);
}

// 2 x K contingency table: expected count of sample s in bin k = (a_k + b_k) N_s / (N_a + N_b).
ChiSquare chi_square_homogeneity(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b)
{
    double na = 0.0, nb = 0.0;
    for (size_t k = 0; k < a.size(); ++k) {
        na += double(a[k]);
        nb += double(b[k]);
    }
    if (na == 0.0 || nb == 0.0)
        return {0.0, 0, 0.0, 0};
    std::vector<Cell> cells;
    for (size_t k = 0; k < a.size(); ++k) {
        const double c = double(a[k]) + double(b[k]);
        if (c > 0.0)
            cells.push_back({{double(a[k]), double(b[k])}, {c * na / (na + nb), c * nb / (na + nb)}, c, 0.0});
    }
    return finish(pool(cells, 10.0), 2);
}

double sidak_level(double alpha, int tests) { return -std::expm1(std::log1p(-alpha) / tests); }

}  // namespace ggxref
