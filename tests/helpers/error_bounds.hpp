// error_bounds.hpp - float-vs-double error checks with two bounds: one
// that 99.9% of the samples must meet and one for the worst sample, which
// the conditioning of a few samples (disk rims, grazing microfacets, very
// small alpha) is allowed to approach.
#pragma once

#include <string>
#include <vector>

namespace ggxtest {

struct ErrorBound {
    const char* name;
    double quantile_999, maximum;
};

// Reports the 99.9% quantile and the maximum of `errors` and checks both.
void check_errors(const std::string& label, const ErrorBound& bound, std::vector<double> errors);

double relative_error(double value, double reference);

} // namespace ggxtest
