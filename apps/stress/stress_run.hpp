// stress_run.hpp - the stability map's measurements: every case of
// stress_grid run on the device (kernels/ggx_stress.cl), on the host
// reference and through the device headers compiled as C++, each outcome classified by failure kind, and the counts per
// cell (alpha row x theta column) of the map.  The rough dielectric's map: stress_dielectric.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "stress_grid.hpp"

namespace ggxapp {

// What can go wrong with one sample:
//   nan_inf          NaN or Inf in m, o, pdf_m, pdf_o or the weight;
//   fallback         the documented answer outside the domain (m = n, pdfs and weight 0;
//                    kernels/ggx_guards.h): the kinds below are not judged for it;
//   not_unit         m or o off unit length by more than 1e-5;
//   m_below          the microfacet normal at or below the surface (m.n <= 0);
//   wasted           o at or below the surface (o.n <= 0): not a failure, counted;
//   pdf_nonpositive  a usable sample (o above the surface) with pdf_o or pdf_m <= 0, or any
//                    sample with a negative pdf_o or pdf_m;
//   pdf_mismatch     its pdf recomputed from (i, o) differs from pdf_o by more than 1e-3 (relative) or is not finite;
//   inaccurate       a case of random uniforms whose m or o lies more than 2e-5 rad from the double reference's
//                    on the same uniforms (neither side's sample NaN, Inf or the fallback; the reference's own map
//                    and a user sampler's, which has none, count 0);
//   inaccurate_edge  a case of the edge and rim uniform pairs, where m's conditioning is worst, more than 2e-3 away.
// The two bounds are the per-sample suites' (tests/helpers/sample_compare.hpp): 99.9% of samples within
// 2e-5 rad, every sample within 2e-3.
enum FailureKind {
    nan_inf, fallback, not_unit, m_below, wasted, pdf_nonpositive, pdf_mismatch, inaccurate, inaccurate_edge,
    failure_kinds
};
constexpr double accuracy_bound = 2e-5, accuracy_bound_edge = 2e-3;  // radians
const char* failure_name(int kind);

struct StressOutcome {
    double m[3], o[3], pdf_m, pdf_o, weight, pdf_again;
    double weight_importance = 0.0;  // a dielectric's: the same sample's weight in importance transport
};
std::array<bool, failure_kinds> classify(const StressOutcome& outcome, const ggxcl::Vec3& normal);

// One cell of a map: its cases, and per kind (FailureKind; a dielectric's map: dielectric::Kind)
// the cases of that kind.
struct Counts {
    std::uint64_t cases = 0;
    std::vector<std::uint64_t> failures;
};
using CellCounts = Counts;

// Counts per cell: cell (row, column) at row * columns + column (a dielectric's map: a layer per eta).
using StressMap = std::vector<Counts>;

// What each side returns for each case, a dielectric's where its eta is not 0: the device's (Backend::stress
// with ggx_stress.cl on OpenCL, its shader on Vulkan; the cases all a conductor's or all a dielectric's;
// guards = false builds the kernel with GGX_GUARDS=0, Method::user runs `user`'s device functions), the
// double reference's, and the device headers' compiled as C++ by this program's compiler (stress_cpp.cpp:
// the same functions the kernel calls, on the host).
std::vector<StressOutcome> device_outcomes(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                                           const std::vector<StressCase>& cases, bool guards = true,
                                           const ggxcl::UserSampler* user = nullptr);
std::vector<StressOutcome> host_outcomes(ggxcl::Method method, const std::vector<StressCase>& cases);
std::vector<StressOutcome> cpp_outcomes(ggxcl::Method method, const std::vector<StressCase>& cases);

// The conductor's map of the same, each outcome classified; guards = false shows what the map looks
// like without the guards.
StressMap device_stress_map(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                            const std::vector<StressCase>& cases, const StressAxes& axes, bool guards = true,
                            const ggxcl::UserSampler* user = nullptr);

// The conductor's map of `outcomes`, the cases whose m or o lies too far from `reference`'s (the same
// cases' reference outcomes) counted as inaccurate or inaccurate_edge.  device_stress_map draws the
// reference's outcomes for its one map; a caller that makes several maps of the same cases draws them
// once (host_outcomes) and passes them here (the reference against itself: its own map).
StressMap map_against(const std::vector<StressOutcome>& outcomes, const std::vector<StressOutcome>& reference,
                      const std::vector<StressCase>& cases, const StressAxes& axes);

} // namespace ggxapp
