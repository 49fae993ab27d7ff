// stress_cpp.cpp - the stress cases through the device headers compiled as C++ (ggx_platform.h):
// what kernels/ggx_stress.cl computes per case, ggx_sample_method and ggx_pdf_method of the
// returned direction (a dielectric: ggx_sample_dielectric_method in both transports and
// ggx_pdf_dielectric_method), run by the host compiler.
#include "ggx_dielectric.h"
#include "ggx_samplers.h"
#include "stress_run.hpp"

namespace ggxapp {

namespace {

ggx_vec3 vec_of(const ggxcl::Vec3& v) { return ggx_vec3_make(v.x, v.y, v.z); }

StressOutcome outcome_of(int method, const StressCase& c)
{
    const ggx_vec3 n = vec_of(c.normal), i = vec_of(c.view);
    const ggx_sample s = ggx_sample_method(method, n, i, c.ax, c.ay, c.u1, c.u2);
    return {{s.m.x, s.m.y, s.m.z}, {s.o.x, s.o.y, s.o.z}, s.pdf_m, s.pdf_o, s.weight,
            ggx_pdf_method(method, n, i, s.o, c.ax, c.ay)};
}

StressOutcome dielectric_outcome_of(int method, const StressCase& c)
{
    const ggx_vec3 n = vec_of(c.normal), i = vec_of(c.view);
    const ggx_sample s = ggx_sample_dielectric_method(method, n, i, c.ax, c.ay, c.eta, 1, c.u1, c.u2, c.u3);
    const ggx_sample imp = ggx_sample_dielectric_method(method, n, i, c.ax, c.ay, c.eta, 0, c.u1, c.u2, c.u3);
    return {{s.m.x, s.m.y, s.m.z}, {s.o.x, s.o.y, s.o.z}, s.pdf_m, s.pdf_o, s.weight,
            ggx_pdf_dielectric_method(method, n, i, s.o, c.ax, c.ay, c.eta), imp.weight};
}

} // namespace

std::vector<StressOutcome> cpp_outcomes(ggxcl::Method method, const std::vector<StressCase>& cases)
{
    std::vector<StressOutcome> outcomes;
    outcomes.reserve(cases.size());
    for (const StressCase& c : cases)
        outcomes.push_back(c.eta != 0.0f ? dielectric_outcome_of(static_cast<int>(method), c)
                                         : outcome_of(static_cast<int>(method), c));
    return outcomes;
}

} // namespace ggxapp
