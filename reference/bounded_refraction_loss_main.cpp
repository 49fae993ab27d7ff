// bounded_refraction_loss_main.cpp - prints, as a Markdown table, the share of a rough dielectric's
// transmitted energy that the bounded cap cannot sample (bounded_lost_transmission), over alpha,
// view angle and index. Built with the tests, not run by ctest.
#include <cmath>
#include <cstdio>

#include "ggx_dielectric.hpp"

namespace {

constexpr double pi = 3.14159265358979323846;

ggxref::Params view(double alpha, double theta_deg)
{
    const double t = theta_deg * pi / 180.0;
    return {alpha, alpha, {std::sin(t), 0.0, std::cos(t)}};
}

void print_rows(double theta, double eta)
{
    std::printf("| %g | %g |", theta, eta);
    for (double alpha : {0.1, 0.3, 0.5, 0.8, 1.0})
        std::printf(" %.3g%% |", 100.0 * ggxref::bounded_lost_transmission(view(alpha, theta), eta));
    std::printf("\n");
}

}  // namespace

int main()
{
    std::printf("Share of the transmitted energy (importance transport) on normals the bounded cap never draws\n\n");
    std::printf("| view (deg) | eta | alpha 0.1 | 0.3 | 0.5 | 0.8 | 1.0 |\n|---|---|---|---|---|---|---|\n");
    for (double eta : {1.33, 1.5, 2.4})
        for (double theta : {0.0, 30.0, 60.0, 75.0, 85.0})
            print_rows(theta, eta);
    print_rows(120.0, 1.5);
    return 0;
}
