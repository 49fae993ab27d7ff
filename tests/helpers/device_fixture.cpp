// device_fixture.cpp - shared device sampler, parameter conversion and grids.
#include "device_fixture.hpp"

#include <cmath>
#include <sstream>

namespace ggxtest {

ggxcl::Sampler& sampler()
{
    static ggxcl::Sampler instance;
    return instance;
}

ggxcl::Method to_library(ggxref::Method method)
{
    return ggxbridge::library_method(method);
}

ggxcl::SampleParams to_library(ggxref::Method method, const ggxref::Params& p, ggxcl::Precision precision)
{
    return ggxbridge::library_params(method, p, precision);
}

ggxref::Params make_params(double ax, double ay, double theta_degrees, double phi_degrees)
{
    const double rad = 3.14159265358979323846 / 180.0;
    double t = theta_degrees * rad, p = phi_degrees * rad;
    ggxref::Params params;
    params.ax = ax;
    params.ay = ay;
    params.i = {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    return params;
}

ggxref::Vec3 unit(const ggxcl::Vec3& v)
{
    double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    return {v.x / len, v.y / len, v.z / len};
}

std::string describe(const ggxref::Params& p)
{
    std::ostringstream out;
    out << "alpha=(" << p.ax << "," << p.ay << ") i=(" << p.i.x << "," << p.i.y << "," << p.i.z << ") n=(" << p.n.x
        << "," << p.n.y << "," << p.n.z << ")";
    return out.str();
}

// The float parameters the device sees, as the reference takes them (the
// bridge's doubles, unit in double), so that both work on the same inputs.
Config as_device_sees(const ggxref::Params& p)
{
    const ggxref::Params seen = ggxbridge::reference_params(ggxcl::normalized(to_library(ggxref::Method::caps, p)));
    return {seen, describe(seen)};
}

// A world normal tilted by `tilt` degrees towards azimuth 120, and the view
// given in the frame of that normal at (theta, phi).
ggxref::Params tilted(double alpha, double theta, double tilt)
{
    ggxref::Params local = make_params(alpha, alpha, theta);
    const double rad = 3.14159265358979323846 / 180.0;
    double ct = std::cos(tilt * rad), st = std::sin(tilt * rad);
    double ca = std::cos(120 * rad), sa = std::sin(120 * rad);
    // Rotation about the axis (-sin a, cos a, 0) by `tilt`: z goes to n.
    auto rotate = [&](ggxref::Vec3 v) {
        double kx = -sa, ky = ca;  // unit axis in the xy-plane
        double dot = kx * v.x + ky * v.y;
        ggxref::Vec3 cross{ky * v.z, -kx * v.z, kx * v.y - ky * v.x};
        return ggxref::Vec3{v.x * ct + cross.x * st + kx * dot * (1 - ct),
                            v.y * ct + cross.y * st + ky * dot * (1 - ct), v.z * ct + cross.z * st};
    };
    local.i = rotate(local.i);
    local.n = rotate({0, 0, 1});
    return local;
}


std::vector<Config> per_sample_grid(ggxref::Method method)
{
    static const double pairs[][2] = {{0.01, 0.01}, {0.01, 0.1}, {0.1, 0.01}, {0.05, 0.15}, {0.1, 0.1},
                                      {0.2, 0.6},   {0.3, 0.3},  {0.5, 0.5},  {1.0, 1.0},   {0.2, 2.0},
                                      {2.0, 0.2},   {1.5, 0.5},  {2.0, 2.0}};
    std::vector<Config> grid;
    for (const auto& a : pairs) {
        if (method == ggxref::Method::caps_iso && a[0] != a[1])
            continue;
        for (double theta : {0.0, 30.0, 60.0, 85.0}) {
            grid.push_back(as_device_sees(make_params(a[0], a[1], theta)));
            if (method == ggxref::Method::caps_iso)
                for (double tilt : {40.0, 150.0})
                    grid.push_back(as_device_sees(tilted(a[0], theta, tilt)));
        }
    }
    return grid;
}

std::vector<Config> distribution_grid(ggxref::Method method)
{
    std::vector<Config> grid;
    if (method == ggxref::Method::caps_iso) {
        for (double alpha : {0.05, 0.3, 1.0, 2.0})
            for (double theta : {0.0, 45.0, 80.0})
                grid.push_back(as_device_sees(make_params(alpha, alpha, theta)));
        for (double alpha : {0.1, 0.6})
            for (double theta : {20.0, 60.0})
                for (double tilt : {35.0, 140.0})
                    grid.push_back(as_device_sees(tilted(alpha, theta, tilt)));
        return grid;
    }
    static const double pairs[][2] = {{0.05, 0.05}, {0.3, 0.3}, {1.0, 1.0}, {2.0, 2.0}, {0.1, 0.5},
                                      {0.6, 0.15},  {0.1, 1.0}};
    for (const auto& a : pairs)
        for (double theta : {0.0, 50.0, 85.0})
            if (grid.size() < 20)
                grid.push_back(as_device_sees(make_params(a[0], a[1], theta)));
    return grid;
}

std::vector<Config> rough_bounded_grid()
{
    std::vector<Config> grid;
    for (auto [ax, ay] : {std::pair{1.5, 1.5}, {1.3, 2.0}})
        for (double theta : {0.0, 52.0, 88.0})
            grid.push_back(as_device_sees(make_params(ax, ay, theta)));
    return grid;
}

ggxcl::SampleSet device_samples(ggxref::Method method, const ggxref::Params& params, std::uint64_t seed,
                                std::uint64_t count, ggxcl::FieldSet fields, ggxcl::Precision precision,
                                ggxcl::Sequence sequence)
{
    ggxcl::SampleParams p = to_library(method, params, precision);
    p.sequence = sequence;
    return sampler().generate(p, {seed, 0, count}, fields);
}

std::array<double, 2> reference_uniforms(ggxcl::Sequence sequence, std::uint64_t seed, std::uint64_t index)
{
    return sequence == ggxcl::Sequence::sobol ? ggxref::sobol_uniforms(seed, index) : ggxref::uniforms(seed, index);
}

std::vector<std::uint64_t> histogram_of(const std::vector<float>& planar, std::uint64_t count, int nz, int nphi)
{
    return ggxref::histogram_directions(planar.data(), planar.data() + count, planar.data() + 2 * count, count, nz,
                                        nphi);
}

bool close_to(double device, double reference, double rel, double abs)
{
    return std::isfinite(device) && std::fabs(device - reference) <= rel * std::fabs(reference) + abs;
}

std::vector<float> run_user_kernel(const std::string& kernels, const std::string& kernel, const std::vector<float>& in,
                                   std::size_t items, std::size_t outputs_per_item)
{
    ggxcl::Sampler& s = sampler();
    cl::Program program(s.context(), ggxcl::kernel_source("ggx_samplers.h") + kernels);
    program.build({s.device()}, ggxcl::device_options(s.device()).c_str());
    cl::Buffer input(s.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(float),
                     const_cast<float*>(in.data()));
    cl::Buffer output(s.context(), CL_MEM_WRITE_ONLY, items * outputs_per_item * sizeof(float));
    cl::Kernel k(program, kernel.c_str());
    k.setArg(0, input);
    k.setArg(1, output);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(items));
    std::vector<float> out(items * outputs_per_item);
    s.queue().enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    return out;
}

} // namespace ggxtest
