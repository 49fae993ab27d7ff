// dielectric_grid.hpp - the configurations the dielectric tests sweep: views
// from above and below (grazing ones too), eta above and below 1 and near 1,
// anisotropic roughness for the tangent-space methods, a tilted normal for
// caps-iso; and their library parameters.
#pragma once

#include <string>
#include <vector>

#include "device_fixture.hpp"

namespace ggxtest {

struct DielectricConfig {
    ggxref::Params params;
    float eta = 1.5f;         // as the library receives it (the reference gets the same float)
    bool importance = false;  // transport
    std::string label;
};

// The grid of `method` (bounded has none: it refuses eta).
std::vector<DielectricConfig> dielectric_grid(ggxref::Method method);

// The library's parameters of a configuration (normalized, with eta and transport).
ggxcl::SampleParams dielectric_params(ggxref::Method method, const DielectricConfig& config,
                                      ggxcl::Precision precision = ggxcl::Precision::precise);

} // namespace ggxtest
