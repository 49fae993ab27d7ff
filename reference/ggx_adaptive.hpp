// ggx_adaptive.hpp - adaptive Gauss-Legendre quadrature on an interval (internal helper of the
// reference quadratures): bisect until the 10- and 20-point rules agree.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/quadrature/gauss.hpp>

namespace ggxref::detail {

struct Tolerance {
    double abs, rel;  // target error max(abs, rel |I|), I the first estimate over the whole interval
};

struct GaussPair {
    double coarse, fine, l1;  // 10- and 20-point rules, 20-point integral of |f|
};

template <class F> GaussPair gauss_pair(const F& f, double a, double b)
{
    using boost::math::quadrature::gauss;
    GaussPair g{};
    g.coarse = gauss<double, 10>::integrate(f, a, b);
    g.fine = gauss<double, 20>::integrate(f, a, b, &g.l1);
    return g;
}

// A piece is accepted when |G20 - G10| is below its share of the target (proportional to its
// width) or below the rounding floor of the rule; pieces at max_depth are accepted as they are
// (noise in f near a singular point cannot be refined away).
template <class F>
double refine_gauss(const F& f, double a, double b, const GaussPair& g, double target_per_length, int depth)
{
    const double floor = 64.0 * std::numeric_limits<double>::epsilon() * g.l1;
    if (depth == 0 || std::fabs(g.fine - g.coarse) <= std::max(target_per_length * (b - a), floor))
        return g.fine;
    const double mid = 0.5 * (a + b);
    return refine_gauss(f, a, mid, gauss_pair(f, a, mid), target_per_length, depth - 1) +
           refine_gauss(f, mid, b, gauss_pair(f, mid, b), target_per_length, depth - 1);
}

template <class F> double adaptive_gauss(const F& f, double a, double b, Tolerance tol, int max_depth = 18)
{
    if (!(b > a))
        return 0.0;
    const GaussPair g = gauss_pair(f, a, b);
    const double target = std::max(tol.abs, tol.rel * std::fabs(g.fine));
    return refine_gauss(f, a, b, g, target / (b - a), max_depth);
}

// The same after x = a + (b - a)(3 s^2 - 2 s^3), s in [0, 1]: the map's zero slope at both ends
// makes square-root endpoint behaviour smooth and softens logarithmic endpoint singularities.
template <class F> double adaptive_gauss_smoothstep(const F& f, double a, double b, Tolerance tol, int max_depth = 18)
{
    const double w = b - a;
    auto g = [&](double s) { return f(a + w * s * s * (3.0 - 2.0 * s)) * 6.0 * w * s * (1.0 - s); };
    return adaptive_gauss(g, 0.0, 1.0, tol, max_depth);
}

// Integral over [a, b] of f with a logarithmic singularity at a: x = a + (b - a) s^4 leaves an
// integrand ~ s^3 log s, smooth enough for the Gauss rules.
template <class F> double adaptive_gauss_quartic(const F& f, double a, double b, Tolerance tol, int max_depth = 18)
{
    const double w = b - a;
    auto g = [&](double s) { return f(a + w * s * s * s * s) * 4.0 * w * s * s * s; };
    return adaptive_gauss(g, 0.0, 1.0, tol, max_depth);
}

// Integral over [a, b] of f that behaves like 1 / sqrt((x - a)^2 + d^2) near a (a point singularity
// at distance d from the line of integration): x = a + d sinh(u) makes it smooth in u.
template <class F>
double adaptive_gauss_sinh(const F& f, double a, double b, double d, Tolerance tol, int max_depth = 18)
{
    auto g = [&](double u) { return f(a + d * std::sinh(u)) * d * std::cosh(u); };
    return adaptive_gauss(g, 0.0, std::asinh((b - a) / d), tol, max_depth);
}

}  // namespace ggxref::detail
