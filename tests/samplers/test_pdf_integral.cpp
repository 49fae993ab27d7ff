// test_pdf_integral.cpp - the device pdf functions (ggx_pdf_bulk) integrate
// to 1 over the sphere of o, and over oz > 0 to the accepted mass the
// reference integrates, within 1e-4.  The quadrature runs over microfacet
// normals in the standard space of the reference (smooth at any alpha), with
// each meridian cut where the integrand has a kink or a jump, and a fixed
// Gauss-Legendre product rule so all nodes go to the device in one batch.
#include <doctest/doctest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "device_fixture.hpp"
#include "ggx_standard_space.hpp"

namespace {

using ggxref::Method;
using ggxref::Vec3;
namespace detail = ggxref::detail;

constexpr int theta_order = 40;
constexpr int phi_nodes = 256;
constexpr double pi = 3.14159265358979323846;

struct Node {
    Vec3 o;
    double weight;  // quadrature weight times |do/dw_m| times |dw_m/dw_ms|
};

// Gauss-Legendre nodes and weights on [a, b].
std::vector<std::pair<double, double>> gauss_nodes(double a, double b)
{
    using rule = boost::math::quadrature::gauss<double, theta_order>;
    std::vector<std::pair<double, double>> nodes;
    double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    for (std::size_t k = 0; k < rule::abscissa().size(); ++k) {
        double x = rule::abscissa()[k], w = rule::weights()[k] * half;
        nodes.push_back({mid + half * x, w});
        if (x != 0.0)
            nodes.push_back({mid - half * x, w});
    }
    return nodes;
}

std::vector<double> meridian_cuts(Method method, const detail::Local& L, double phi)
{
    std::vector<double> cuts = detail::cuts_visible(L, phi);
    std::vector<double> horizon = detail::cuts_horizon(L, phi);
    cuts.insert(cuts.end(), horizon.begin(), horizon.end());
    if (method == Method::bounded) {
        std::vector<double> cap = detail::cuts_bounded_cap(L, phi, ggxref::bounded_k(L.i, L.ax, L.ay));
        cuts.insert(cuts.end(), cap.begin(), cap.end());
    }
    cuts.push_back(0.0);
    cuts.push_back(0.5 * pi);
    std::sort(cuts.begin(), cuts.end());
    return cuts;
}

// Nodes covering every o once: o = reflect(i, m) over the hemisphere of m.
std::vector<Node> quadrature_nodes(Method method, const ggxref::Params& params)
{
    detail::Local L = method == Method::caps_iso ? detail::isotropic_problem(params) : detail::tangent_problem(params);
    std::vector<Node> nodes;
    for (int p = 0; p < phi_nodes; ++p) {
        double phi = 2.0 * pi * (p + 0.5) / phi_nodes, phi_weight = 2.0 * pi / phi_nodes;
        std::vector<double> cuts = meridian_cuts(method, L, phi);
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            if (!(cuts[c + 1] > cuts[c]))
                continue;
            for (auto [theta, w] : gauss_nodes(cuts[c], cuts[c + 1])) {
                double st = std::sin(theta);
                Vec3 ms{st * std::cos(phi), st * std::sin(phi), std::cos(theta)};
                Vec3 a{L.ax * ms.x, L.ay * ms.y, ms.z};
                double len = std::sqrt(dot(a, a));
                Vec3 m = (1.0 / len) * a;
                double i_dot_m = dot(L.i, m);
                Vec3 o = 2.0 * i_dot_m * m - L.i;
                double jacobian = 4.0 * std::fabs(i_dot_m) * L.ax * L.ay / (len * len * len) * st;
                nodes.push_back({L.outer(o), w * phi_weight * jacobian});
            }
        }
    }
    return nodes;
}

struct Masses {
    double total = 0, upper = 0;
};

Masses device_integral(Method method, const ggxref::Params& params)
{
    std::vector<Node> nodes = quadrature_nodes(method, params);
    std::vector<ggxcl::Vec3> directions;
    for (const Node& n : nodes)
        directions.push_back({float(n.o.x), float(n.o.y), float(n.o.z)});
    std::vector<float> pdf = ggxtest::sampler().pdf(ggxtest::to_library(method, params), directions);
    Masses mass;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        mass.total += nodes[k].weight * pdf[k];
        if (dot(nodes[k].o, params.n) > 0.0)
            mass.upper += nodes[k].weight * pdf[k];
    }
    return mass;
}

void check_method(Method method, const std::vector<ggxtest::Config>& grid, std::size_t step)
{
    for (std::size_t k = 0; k < grid.size(); k += step) {
        const ggxref::Params& params = grid[k].params;
        Masses mass = device_integral(method, params);
        CAPTURE(grid[k].label);
        CAPTURE(mass.total);
        CHECK(std::fabs(mass.total - 1.0) <= 1e-4);
        if (method == Method::bounded || method == Method::ndf) {
            double accepted = ggxref::integrate_pdf_o_upper(method, params);
            CAPTURE(accepted);
            CHECK(std::fabs(mass.upper - accepted) <= 1e-4);
        }
    }
}

// Every other configuration of the per-sample grid keeps the run short.
void check_method(Method method) { check_method(method, ggxtest::per_sample_grid(method), 2); }

} // namespace

TEST_CASE("device pdf of ndf integrates to 1") { check_method(Method::ndf); }
TEST_CASE("device pdf of heitz integrates to 1") { check_method(Method::heitz); }
TEST_CASE("device pdf of heitz2017 integrates to 1") { check_method(Method::heitz2017); }
TEST_CASE("device pdf of caps integrates to 1") { check_method(Method::caps); }
TEST_CASE("device pdf of caps-iso integrates to 1") { check_method(Method::caps_iso); }
TEST_CASE("device pdf of bounded integrates to 1, and to the accepted mass over oz > 0") { check_method(Method::bounded); }
TEST_CASE("the same for bounded where both alphas exceed 1 (k < 0)")
{
    check_method(Method::bounded, ggxtest::rough_bounded_grid(), 1);
}

TEST_CASE("negative control: the quadrature resolves the mass the bound moves above the horizon")
{
    // Both pdfs integrate to 1, but bounded puts its removed mass r = (1 - k) iz/(iz + t)
    // above the horizon: the accepted masses must differ by far more than the tolerance.
    ggxref::Params params = ggxtest::make_params(0.5, 0.5, 40.0);
    Masses bounded = device_integral(Method::bounded, params);
    Masses caps = device_integral(Method::caps, params);
    CHECK(std::fabs(bounded.total - 1.0) <= 1e-4);
    CHECK(std::fabs(caps.total - 1.0) <= 1e-4);
    CHECK(std::fabs(bounded.upper - caps.upper) > 1e-2);  // different accepted masses are told apart
}
