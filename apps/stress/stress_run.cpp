// stress_run.cpp - device and host runs of the stress cases, classified.
#include "stress_run.hpp"

#include <cmath>

#include "reference_bridge.hpp"

namespace ggxapp {

namespace {

constexpr int input_planes = 10, output_planes = 10;

bool all_finite(const StressOutcome& s)
{
    double values[] = {s.m[0], s.m[1], s.m[2], s.o[0], s.o[1], s.o[2], s.pdf_m, s.pdf_o, s.weight};
    for (double v : values)
        if (!std::isfinite(v))
            return false;
    return true;
}

double dot3(const double* a, const ggxcl::Vec3& n)
{
    return a[0] * n.x + a[1] * n.y + a[2] * n.z;
}

double length3(const double* a)
{
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

std::vector<float> planar_inputs(const std::vector<StressCase>& cases)
{
    const std::size_t n = cases.size();
    std::vector<float> in(input_planes * n);
    for (std::size_t j = 0; j < n; ++j) {
        const StressCase& c = cases[j];
        float values[input_planes] = {c.ax,       c.ay,       c.view.x, c.view.y, c.view.z,
                                      c.normal.x, c.normal.y, c.normal.z, c.u1,   c.u2};
        for (int k = 0; k < input_planes; ++k)
            in[k * n + j] = values[k];
    }
    return in;
}

} // namespace

void count_outcome(StressMap& map, const StressAxes& axes, const StressCase& c, const StressOutcome& outcome)
{
    CellCounts& cell = map[std::size_t(c.row) * axes.cos_theta.size() + c.column];
    ++cell.cases;
    std::array<bool, failure_kinds> kinds = classify(outcome, c.normal);
    for (int k = 0; k < failure_kinds; ++k)
        cell.failures[k] += kinds[k];
}

std::string stress_defines(ggxcl::Method method, bool guards)
{
    return "-DGGX_METHOD=" + std::to_string(static_cast<int>(method)) + " -DGGX_GUARDS=" + (guards ? "1" : "0");
}

namespace {

// The precision mode's options are the library's own (ggxcl::precision_options).
std::string stress_options(const cl::Device& device, ggxcl::Method method, ggxcl::Precision precision, bool guards)
{
    return stress_defines(method, guards) + ggxcl::device_options(device) + ggxcl::precision_options(device, precision);
}

} // namespace

const char* failure_name(int kind)
{
    static const char* names[] = {"nan_inf",         "fallback",   "not_unit", "m_below", "wasted",
                                  "pdf_nonpositive", "pdf_mismatch"};
    return names[kind];
}

std::array<bool, failure_kinds> classify(const StressOutcome& s, const ggxcl::Vec3& normal)
{
    std::array<bool, failure_kinds> kinds{};
    kinds[nan_inf] = !all_finite(s);
    if (kinds[nan_inf])
        return kinds;
    kinds[fallback] = s.pdf_m == 0.0 && s.pdf_o == 0.0 && s.weight == 0.0 && s.m[0] == normal.x &&
                      s.m[1] == normal.y && s.m[2] == normal.z;
    if (kinds[fallback])
        return kinds;
    kinds[not_unit] = std::fabs(length3(s.m) - 1.0) > 1e-5 || std::fabs(length3(s.o) - 1.0) > 1e-5;
    kinds[m_below] = dot3(s.m, normal) <= 0.0;
    kinds[wasted] = dot3(s.o, normal) <= 0.0;
    kinds[pdf_nonpositive] = s.pdf_o < 0.0 || s.pdf_m < 0.0;  // no density is negative, wasted or not
    if (!kinds[wasted]) {
        kinds[pdf_nonpositive] = !(s.pdf_o > 0.0) || !(s.pdf_m > 0.0);
        kinds[pdf_mismatch] = s.pdf_o > 0.0 && (!std::isfinite(s.pdf_again) ||
                                                std::fabs(s.pdf_again - s.pdf_o) > 1e-3 * s.pdf_o);
    }
    return kinds;
}

StressMap device_stress_map(ggxcl::Sampler& sampler, ggxcl::Method method, ggxcl::Precision precision,
                            const std::vector<StressCase>& cases, const StressAxes& axes, bool guards)
{
    const std::size_t n = cases.size();
    std::vector<float> in = planar_inputs(cases), out(output_planes * n);
    cl::Program program(sampler.context(), ggxcl::kernel_source("ggx_stress.cl"));
    program.build({sampler.device()}, stress_options(sampler.device(), method, precision, guards).c_str());
    cl::Kernel kernel(program, "ggx_stress");
    cl::Buffer in_buffer(sampler.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(float),
                         in.data());
    cl::Buffer out_buffer(sampler.context(), CL_MEM_WRITE_ONLY, out.size() * sizeof(float));
    kernel.setArg(0, cl_uint(n));
    kernel.setArg(1, in_buffer);
    kernel.setArg(2, out_buffer);
    std::size_t global = (n + 255) / 256 * 256;
    sampler.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(256));
    sampler.queue().enqueueReadBuffer(out_buffer, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    StressMap map(axes.alphas.size() * axes.cos_theta.size());
    for (std::size_t j = 0; j < n; ++j) {
        auto at = [&](int k) { return double(out[k * n + j]); };
        StressOutcome s{{at(0), at(1), at(2)}, {at(3), at(4), at(5)}, at(6), at(7), at(8), at(9)};
        count_outcome(map, axes, cases[j], s);
    }
    return map;
}

StressMap host_stress_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes)
{
    StressMap map(axes.alphas.size() * axes.cos_theta.size());
    ggxref::Method ref = ggxbridge::reference_method(method);
    for (const StressCase& c : cases) {
        ggxref::Params p{c.ax, c.ay, {c.view.x, c.view.y, c.view.z}, {c.normal.x, c.normal.y, c.normal.z}};
        ggxref::Sample r = ggxref::sample(ref, p, c.u1, c.u2);
        StressOutcome s{{r.m.x, r.m.y, r.m.z}, {r.o.x, r.o.y, r.o.z}, r.pdf_m, r.pdf_o, r.weight,
                        ggxref::pdf_o(ref, p, r.o)};
        count_outcome(map, axes, c, s);
    }
    return map;
}

} // namespace ggxapp
