// error_bounds.cpp - quantile and maximum checks of error samples.
#include "error_bounds.hpp"

#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

namespace ggxtest {

void check_errors(const std::string& label, const ErrorBound& bound, std::vector<double> errors)
{
    REQUIRE(!errors.empty());
    double worst = *std::max_element(errors.begin(), errors.end());
    std::size_t k = std::size_t(0.999 * double(errors.size() - 1));
    std::nth_element(errors.begin(), errors.begin() + k, errors.end());
    MESSAGE(label << " " << std::string(bound.name) << ": 99.9% <= " << errors[k] << ", max " << worst);
    CHECK(errors[k] <= bound.quantile_999);
    CHECK(worst <= bound.maximum);
}

double relative_error(double value, double reference)
{
    return reference == 0.0 ? std::fabs(value) : std::fabs(value - reference) / std::fabs(reference);
}

} // namespace ggxtest
