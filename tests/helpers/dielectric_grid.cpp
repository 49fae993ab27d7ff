// dielectric_grid.cpp - the dielectric tests' configurations.
#include "dielectric_grid.hpp"

#include <cmath>

namespace ggxtest {

namespace {

struct Row {
    double ax, ay, theta;
    float eta;
    bool importance;
};

// The view of `params` carried onto a tilted world normal (for caps-iso): i = t sin + n cos.
ggxref::Params tilted(const ggxref::Params& params)
{
    const ggxref::Vec3 n = ggxref::normalize({0.3, -0.2, 0.93});
    const ggxref::Vec3 t = ggxref::any_perpendicular(n), b = ggxref::cross(n, t);
    const ggxref::Vec3 i = params.i;
    ggxref::Params out = params;
    out.n = n;
    out.i = ggxref::normalize(i.x * t + i.y * b + i.z * n);
    return out;
}

std::string label_of(const Row& r)
{
    return "alpha " + std::to_string(r.ax) + "," + std::to_string(r.ay) + " theta " + std::to_string(r.theta) +
           " eta " + std::to_string(r.eta) + (r.importance ? " importance" : " radiance");
}

} // namespace

std::vector<DielectricConfig> dielectric_grid(ggxref::Method method)
{
    if (method == ggxref::Method::bounded)
        return {};
    const bool isotropic = method == ggxref::Method::caps_iso;
    const Row rows[] = {
        {0.3, 0.3, 30.0, 1.5f, false},   {0.6, 0.6, 60.0, 1.5f, true},     {0.15, 0.15, 80.0, 1.33f, false},
        {1.0, 1.0, 45.0, 2.4f, true},    {0.5, 0.5, 135.0, 1.5f, false},   {0.4, 0.4, 160.0, 1.33f, true},
        {0.3, 0.3, 20.0, 1.0f / 1.5f, false}, {0.5, 0.5, 40.0, 1.05f, false},
        {0.5, isotropic ? 0.5 : 0.2, 50.0, 1.5f, false},
    };
    std::vector<DielectricConfig> grid;
    for (const Row& r : rows) {
        DielectricConfig c{make_params(r.ax, r.ay, r.theta), r.eta, r.importance, label_of(r)};
        if (isotropic && &r == &rows[std::size(rows) - 1]) {
            c.params = tilted(c.params);
            c.label += " tilted normal";
        }
        grid.push_back(c);
    }
    return grid;
}

ggxcl::SampleParams dielectric_params(ggxref::Method method, const DielectricConfig& config,
                                      ggxcl::Precision precision)
{
    ggxcl::SampleParams p = to_library(method, config.params, precision);
    p.eta = config.eta;
    p.transport = config.importance ? ggxcl::Transport::importance : ggxcl::Transport::radiance;
    return p;
}

} // namespace ggxtest
