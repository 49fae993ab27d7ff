// stress_dielectric.hpp - the rough dielectric's stability map (`ggx stress --eta`): the cases of
// dielectric_cases run through kernels/ggx_stress.cl built with GGX_DIELECTRIC=1 (the device's
// ggx_sample_dielectric_method and ggx_pdf_dielectric_method), through the double reference
// (dielectric_sample, dielectric_pdf_o) and through the device headers compiled as C++; each outcome
// classified, counted per cell (eta layer x alpha row x theta column).
#pragma once

#include "stress_run.hpp"

namespace ggxapp::dielectric {

// What one dielectric sample shows.  The view's side is that of i.n (i.n = 0 counts as above, as
// the device functions have it; within 1e-6 of the surface about a tilted caps-iso normal, where
// float and double may disagree on the sign, either side is accepted: the reading with fewer failures).
//   nan_inf          NaN or Inf in m, o, pdf_m, pdf_o, either weight or the recomputed pdf;
//   fallback         m = o = the normal on the view's side, pdfs and weights 0 (kernels/ggx_guards.h;
//                    docs/STABILITY.md): the kinds below are not judged for it;
//   not_unit         m or o off unit length by more than 1e-5 (a refraction beyond the critical
//                    angle, its cosine clamped to 0, comes out longer than 1 and lands here);
//   m_side           m not facing the view's side (m.n of the wrong sign, or 0);
//   invalid          no density (pdf_o = 0): not a failure, counted;
//   transmitted      a valid sample on the other side of the surface: not a failure, counted;
//   bad_weight       a negative weight, or a nonzero one without density;
//   off_lobe         a valid sample whose o is neither the reflection of i about m (to 1e-4) nor its
//                    refraction (o.m < 0 and Snell's i_t + eta' o_t = 0 to 1e-4 (1 + eta'), eta' the
//                    index seen from the view's side), or lies in the surface;
//   pdf_nonpositive  a negative pdf_o or pdf_m, or a valid sample with pdf_m <= 0;
//   pdf_mismatch     a valid sample whose pdf recomputed from (i, o) differs from pdf_o by more than 1e-3
//                    (relative), as the conductor's map.
enum Kind { nan_inf, fallback, not_unit, m_side, invalid, transmitted, bad_weight, off_lobe, pdf_nonpositive,
            pdf_mismatch, kinds };
const char* kind_name(int kind);
// invalid and transmitted are counts, not failures.
bool is_failure(int kind);

// Counts per cell, a count per Kind: cell (eta layer e, row, column) at (e * rows + row) * columns + column.
using Counts = ggxapp::Counts;
using Map = StressMap;

std::array<bool, kinds> classify(const StressOutcome& outcome, const StressCase& c);

// What each side returns for each case: stress_run.hpp's, which run a case whose eta is not 0 (every
// case of dielectric_cases) as a dielectric's.
using ggxapp::cpp_outcomes;
using ggxapp::device_outcomes;
using ggxapp::host_outcomes;

// The same classified and counted per cell; guards = false builds the kernel with GGX_GUARDS=0.
Map device_map(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
               const std::vector<StressCase>& cases, const StressAxes& axes, bool guards = true);
Map host_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes);
Map cpp_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes);

} // namespace ggxapp::dielectric
