// stress_run.cpp - the stress cases' outcomes on the device and the host reference, classified (the
// conductor's kinds, stress_run.hpp; the rough dielectric's, stress_dielectric.hpp) and counted per cell.
#include "stress_run.hpp"

#include <algorithm>
#include <cmath>

#include "reference_bridge.hpp"
#include "stress_dielectric.hpp"

namespace ggxapp {

namespace {

// Whether m, o, pdf_m, pdf_o and the weight are finite; for a dielectric also its recomputed pdf and its
// weight in importance transport (a conductor's recomputed pdf is judged by pdf_mismatch).
bool all_finite(const StressOutcome& s, bool dielectric)
{
    const double values[] = {s.m[0],  s.m[1],  s.m[2],   s.o[0],      s.o[1],           s.o[2],
                             s.pdf_m, s.pdf_o, s.weight, s.pdf_again, s.weight_importance};
    return std::all_of(values, values + (dielectric ? 11 : 9), [](double v) { return std::isfinite(v); });
}

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double length(const double* a) { return std::sqrt(dot(a, a)); }

// m or o off unit length by more than 1e-5.
bool off_unit(const StressOutcome& s)
{
    return std::fabs(length(s.m) - 1.0) > 1e-5 || std::fabs(length(s.o) - 1.0) > 1e-5;
}

double angle_between(const double* a, const double* b)
{
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return std::atan2(length(c), dot(a, b));
}

} // namespace

const char* failure_name(int kind)
{
    static const char* names[] = {"nan_inf",         "fallback",     "not_unit",   "m_below",        "wasted",
                                  "pdf_nonpositive", "pdf_mismatch", "inaccurate", "inaccurate_edge"};
    return names[kind];
}

std::array<bool, failure_kinds> classify(const StressOutcome& s, const ggxcl::Vec3& normal)
{
    std::array<bool, failure_kinds> kinds{};
    kinds[nan_inf] = !all_finite(s, false);
    if (kinds[nan_inf])
        return kinds;
    kinds[fallback] = s.pdf_m == 0.0 && s.pdf_o == 0.0 && s.weight == 0.0 && s.m[0] == normal.x &&
                      s.m[1] == normal.y && s.m[2] == normal.z;
    if (kinds[fallback])
        return kinds;
    const double n[3] = {normal.x, normal.y, normal.z};
    kinds[not_unit] = off_unit(s);
    kinds[m_below] = dot(s.m, n) <= 0.0;
    kinds[wasted] = dot(s.o, n) <= 0.0;
    kinds[pdf_nonpositive] = s.pdf_o < 0.0 || s.pdf_m < 0.0;  // no density is negative, wasted or not
    if (!kinds[wasted]) {
        kinds[pdf_nonpositive] = !(s.pdf_o > 0.0) || !(s.pdf_m > 0.0);
        kinds[pdf_mismatch] = s.pdf_o > 0.0 && (!std::isfinite(s.pdf_again) ||
                                                std::fabs(s.pdf_again - s.pdf_o) > 1e-3 * s.pdf_o);
    }
    return kinds;
}

// ---- The rough dielectric's classification (stress_dielectric.hpp) ----

namespace dielectric {

namespace {

// Within 1e-6 of the surface about a tilted normal (caps-iso's world space), float and double may
// disagree on which side a direction is.
bool near_surface(const StressCase& c, double height)
{
    return !(c.normal.x == 0.0f && c.normal.y == 0.0f) && std::fabs(height) < 1e-6;
}

// The view's side: 1 for i.n >= 0, -1 below, 0 (either) near the surface about a tilted normal.
int view_side(const StressCase& c)
{
    const double i[3] = {c.view.x, c.view.y, c.view.z}, n[3] = {c.normal.x, c.normal.y, c.normal.z};
    const double height = dot(i, n);
    if (near_surface(c, height))
        return 0;
    return height >= 0.0 ? 1 : -1;
}

// m = o = sign n (to 1e-6: caps-iso mirrors a tilted normal in float), pdfs and weights 0.
bool at_normal(const double* v, const double* n, int sign)
{
    for (int k = 0; k < 3; ++k)
        if (!(std::fabs(v[k] - sign * n[k]) <= 1e-6))
            return false;
    return true;
}

bool is_fallback(const StressOutcome& s, const double* n, int side)
{
    if (!(s.pdf_m == 0.0 && s.pdf_o == 0.0 && s.weight == 0.0 && s.weight_importance == 0.0))
        return false;
    for (int sign : {1, -1})
        if ((side == 0 || side == sign) && at_normal(s.m, n, sign) && at_normal(s.o, n, sign))
            return true;
    return false;
}

double distance(const double* a, const double* b)
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return std::sqrt(dot(d, d));
}

// How a sample is read: the view's side (1 above, -1 below) and whether o crossed the surface.
struct Reading {
    int sign;
    bool across;
};

// Every reading of the sample: one, or, near the surface about a tilted normal, both sides of the
// view and of o.
std::vector<Reading> readings_of(const StressOutcome& s, const StressCase& c, const double* n)
{
    const int side = view_side(c);
    const double on = dot(s.o, n);
    std::vector<Reading> readings;
    for (int sign : {1, -1}) {
        if (side != 0 && side != sign)
            continue;
        if (near_surface(c, on))
            readings.insert(readings.end(), {{sign, false}, {sign, true}});
        else
            readings.push_back({sign, sign * on < 0.0});
    }
    return readings;
}

// The index seen from the view's side.
double eta_seen(const StressCase& c, int sign) { return sign > 0 ? double(c.eta) : 1.0 / double(c.eta); }

// A valid sample's o against its lobe: a reflection is 2 (i.m) m - i; a transmission a refraction
// (o.m < 0, and Snell's law on the tangential parts: i_t + eta' o_t = 0); o in the surface is neither.
bool outside_lobe(const StressOutcome& s, const StressCase& c, const double* n, Reading r)
{
    const double i[3] = {c.view.x, c.view.y, c.view.z};
    const double im = dot(i, s.m), on = dot(s.o, n);
    if (on == 0.0 && !near_surface(c, on))
        return true;
    if (!r.across) {
        const double reflected[3] = {2.0 * im * s.m[0] - i[0], 2.0 * im * s.m[1] - i[1], 2.0 * im * s.m[2] - i[2]};
        return distance(s.o, reflected) > 1e-4;
    }
    const double eta = eta_seen(c, r.sign), om = dot(s.o, s.m);
    double t[3];
    for (int k = 0; k < 3; ++k)
        t[k] = (i[k] - im * s.m[k]) + eta * (s.o[k] - om * s.m[k]);
    return !(om < 0.0) || std::sqrt(dot(t, t)) > 1e-4 * (1.0 + eta);
}

// Weights: never negative, 0 without density, and radiance = importance / eta'^2 for a transmission.
bool weight_wrong(const StressOutcome& s, const StressCase& c, bool valid, Reading r)
{
    if (s.weight < 0.0 || s.weight_importance < 0.0)
        return true;
    if (!valid)
        return s.weight != 0.0 || s.weight_importance != 0.0;
    const double eta = eta_seen(c, r.sign);
    const double expected = r.across ? s.weight_importance / (eta * eta) : s.weight_importance;
    return std::fabs(s.weight - expected) > 1e-5 * expected;
}

} // namespace

const char* kind_name(int kind)
{
    static const char* names[] = {"nan_inf",     "fallback",   "not_unit", "m_side",          "invalid",
                                  "transmitted", "bad_weight", "off_lobe", "pdf_nonpositive", "pdf_mismatch"};
    return names[kind];
}

bool is_failure(int kind) { return kind != invalid && kind != transmitted; }

namespace {

// The kinds after nan_inf and fallback, for one reading of the sample.
std::array<bool, kinds> judge(const StressOutcome& s, const StressCase& c, const double* n, Reading r)
{
    std::array<bool, kinds> k{};
    const bool valid = s.pdf_o > 0.0;
    k[not_unit] = off_unit(s);
    k[m_side] = !(r.sign * dot(s.m, n) > 0.0);
    k[invalid] = !valid;
    k[transmitted] = valid && r.across;
    k[bad_weight] = weight_wrong(s, c, valid, r);
    k[pdf_nonpositive] = s.pdf_o < 0.0 || s.pdf_m < 0.0 || (valid && !(s.pdf_m > 0.0));
    if (valid) {
        k[off_lobe] = outside_lobe(s, c, n, r);
        k[pdf_mismatch] = !(std::fabs(s.pdf_again - s.pdf_o) <= 1e-3 * s.pdf_o);
    }
    return k;
}

int failures(const std::array<bool, kinds>& k)
{
    int count = 0;
    for (int kind = 0; kind < kinds; ++kind)
        count += is_failure(kind) && k[kind];
    return count;
}

} // namespace

std::array<bool, kinds> classify(const StressOutcome& s, const StressCase& c)
{
    std::array<bool, kinds> k{};
    k[nan_inf] = !all_finite(s, true);
    const double n[3] = {c.normal.x, c.normal.y, c.normal.z};
    k[fallback] = !k[nan_inf] && is_fallback(s, n, view_side(c));
    if (k[nan_inf] || k[fallback])
        return k;
    bool first = true;
    for (const Reading& r : readings_of(s, c, n)) {  // the reading with the fewest failures
        const std::array<bool, kinds> found = judge(s, c, n, r);
        if (first || failures(found) < failures(k))
            k = found;
        first = false;
    }
    return k;
}

} // namespace dielectric

// ---- The runs and their maps ----

namespace {

// The cases as Backend::stress takes them, plane k holding input k of every case: ax, ay, the view,
// the normal, u1, u2 (10 planes), and for a dielectric u3 and eta (12).
std::vector<float> planar_inputs(const std::vector<StressCase>& cases, bool dielectric)
{
    const std::size_t n = cases.size(), planes = dielectric ? 12 : 10;
    std::vector<float> in(planes * n);
    for (std::size_t j = 0; j < n; ++j) {
        const StressCase& c = cases[j];
        const float values[] = {c.ax,       c.ay,       c.view.x, c.view.y, c.view.z, c.normal.x,
                                c.normal.y, c.normal.z, c.u1,     c.u2,     c.u3,     c.eta};
        for (std::size_t k = 0; k < planes; ++k)
            in[k * n + j] = values[k];
    }
    return in;
}

// Each case classified (classify(j): its kinds, an array of Kinds flags) and counted in its cell,
// (layer * rows + row) * columns + column: the layer that of the case's eta in axes.etas (a conductor's
// map has no etas: layer 0).
template <std::size_t Kinds, class Classify>
StressMap map_of(const std::vector<StressCase>& cases, const StressAxes& axes, Classify classify)
{
    const std::size_t rows = axes.alphas.size(), columns = axes.cos_theta.size();
    const std::size_t layers = std::max<std::size_t>(axes.etas.size(), 1);
    StressMap map(layers * rows * columns, {0, std::vector<std::uint64_t>(Kinds)});
    for (std::size_t j = 0; j < cases.size(); ++j) {
        const StressCase& c = cases[j];
        const std::size_t layer = std::find(axes.etas.begin(), axes.etas.end(), c.eta) - axes.etas.begin();
        Counts& cell = map.at((layer * rows + c.row) * columns + c.column);
        ++cell.cases;
        const std::array<bool, Kinds> found = classify(j);
        for (std::size_t k = 0; k < Kinds; ++k)
            cell.failures[k] += found[k];
    }
    return map;
}

// The conductor's kinds of each outcome, or the dielectric's, counted per cell.
StressMap conductor_map(const std::vector<StressOutcome>& outcomes, const std::vector<StressCase>& cases,
                        const StressAxes& axes)
{
    return map_of<failure_kinds>(cases, axes, [&](std::size_t j) { return classify(outcomes[j], cases[j].normal); });
}

dielectric::Map dielectric_map(const std::vector<StressOutcome>& outcomes, const std::vector<StressCase>& cases,
                               const StressAxes& axes)
{
    return map_of<dielectric::kinds>(cases, axes, [&](std::size_t j) { return dielectric::classify(outcomes[j], cases[j]); });
}

} // namespace

StressMap map_against(const std::vector<StressOutcome>& outcomes, const std::vector<StressOutcome>& reference,
                      const std::vector<StressCase>& cases, const StressAxes& axes)
{
    return map_of<failure_kinds>(cases, axes, [&](std::size_t j) {
        const StressCase& c = cases[j];
        std::array<bool, failure_kinds> kinds = classify(outcomes[j], c.normal);
        const std::array<bool, failure_kinds> theirs = classify(reference[j], c.normal);
        if (kinds[nan_inf] || kinds[fallback] || theirs[nan_inf] || theirs[fallback])
            return kinds;
        const double angle = std::max(angle_between(outcomes[j].m, reference[j].m),
                                      angle_between(outcomes[j].o, reference[j].o));
        kinds[c.random ? inaccurate : inaccurate_edge] = !(angle <= (c.random ? accuracy_bound : accuracy_bound_edge));
        return kinds;
    });
}

std::vector<StressOutcome> device_outcomes(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                                           const std::vector<StressCase>& cases, bool guards,
                                           const ggxcl::UserSampler* user)
{
    const std::size_t n = cases.size();
    const bool dielectric = n > 0 && cases.front().eta != 0.0f;
    const std::vector<float> out = device.stress({method, precision, guards, dielectric, user},
                                                 planar_inputs(cases, dielectric), std::uint32_t(n));
    std::vector<StressOutcome> outcomes(n);
    for (std::size_t j = 0; j < n; ++j) {
        auto at = [&](int k) { return double(out[k * n + j]); };  // 10 planes, a dielectric's 11
        outcomes[j] = {{at(0), at(1), at(2)}, {at(3), at(4), at(5)}, at(6), at(7), at(8), at(9),
                       dielectric ? at(10) : 0.0};
    }
    return outcomes;
}

std::vector<StressOutcome> host_outcomes(ggxcl::Method method, const std::vector<StressCase>& cases)
{
    std::vector<StressOutcome> outcomes;
    outcomes.reserve(cases.size());
    const ggxref::Method ref = ggxbridge::reference_method(method);
    for (const StressCase& c : cases) {
        // The float vectors as they are (not the bridge's unit doubles): a view exactly opposite
        // the normal in float stays exactly opposite, where unit doubles can miss -1 by rounding.
        const ggxref::Params p{c.ax, c.ay, {c.view.x, c.view.y, c.view.z}, {c.normal.x, c.normal.y, c.normal.z}};
        const bool dielectric = c.eta != 0.0f;
        const ggxref::Sample r = dielectric ? ggxref::dielectric_sample(ref, p, c.eta, true, c.u1, c.u2, c.u3)
                                            : ggxref::sample(ref, p, c.u1, c.u2);
        const double again = dielectric ? ggxref::dielectric_pdf_o(ref, p, c.eta, r.o) : ggxref::pdf_o(ref, p, r.o);
        const double importance =
            dielectric ? ggxref::dielectric_sample(ref, p, c.eta, false, c.u1, c.u2, c.u3).weight : 0.0;
        outcomes.push_back(
            {{r.m.x, r.m.y, r.m.z}, {r.o.x, r.o.y, r.o.z}, r.pdf_m, r.pdf_o, r.weight, again, importance});
    }
    return outcomes;
}

StressMap device_stress_map(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                            const std::vector<StressCase>& cases, const StressAxes& axes, bool guards,
                            const ggxcl::UserSampler* user)
{
    const std::vector<StressOutcome> outcomes = device_outcomes(device, method, precision, cases, guards, user);
    if (user)  // no reference to hold it to
        return conductor_map(outcomes, cases, axes);
    return map_against(outcomes, host_outcomes(method, cases), cases, axes);
}

dielectric::Map dielectric::device_map(ggxcl::Backend& device, ggxcl::Method method, ggxcl::Precision precision,
                                       const std::vector<StressCase>& cases, const StressAxes& axes, bool guards)
{
    return dielectric_map(device_outcomes(device, method, precision, cases, guards), cases, axes);
}

dielectric::Map dielectric::host_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes)
{
    return dielectric_map(host_outcomes(method, cases), cases, axes);
}

dielectric::Map dielectric::cpp_map(ggxcl::Method method, const std::vector<StressCase>& cases, const StressAxes& axes)
{
    return dielectric_map(cpp_outcomes(method, cases), cases, axes);
}

} // namespace ggxapp
