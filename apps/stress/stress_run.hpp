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
//   pdf_mismatch     its pdf recomputed from (i, o) differs from pdf_o by more than 1e-3 (relative) or is not finite.
enum FailureKind { nan_inf, fallback, not_unit, m_below, wasted, pdf_nonpositive, pdf_mismatch, failure_kinds };
const char* failure_name(int kind);

struct StressOutcome {
    double m[3], o[3], pdf_m, pdf_o, weight, pdf_again;
    double weight_importance = 0.0;  // a dielectric's: the same sample's weight in importance transport
};
std::array<bool, failure_kinds> classify(const StressOutcome& outcome, const ggxcl::Vec3& normal);

template <std::size_t Kinds>
struct Counts {
    std::uint64_t cases = 0;
    std::array<std::uint64_t, Kinds> failures{};
};
using CellCounts = Counts<failure_kinds>;

// Counts per cell, row-major: cell (row, column) at row * columns + column.
using StressMap = std::vector<CellCounts>;

// The map's cases on `device` (Backend::stress: ggx_stress.cl on OpenCL, its shader on Vulkan);
// guards = false builds the kernel with GGX_GUARDS=0 (what the map looks like without them).
// Method::user runs `user`'s device functions.
StressMap device_stress_map(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                            const std::vector<StressCase>& cases, const StressAxes& axes, bool guards = true,
                            const ggxcl::UserSampler* user = nullptr);
StressMap host_stress_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes);
// The device headers compiled as C++ by this program's compiler (stress_cpp.cpp): the same
// functions the kernel calls, on the host.
StressMap cpp_stress_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes);

// Adds one classified outcome of case c to its cell of the map.
void count_outcome(StressMap& map, const StressAxes& axes, const StressCase& c, const StressOutcome& outcome);

} // namespace ggxapp
