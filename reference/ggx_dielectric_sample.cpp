// ggx_dielectric_sample.cpp - a rough dielectric's sample from any method's microfacet normal, and
// its density recomputed from (i, o) (Walter et al. 2007, Sec. 5.3 and eqs. 38-41; SPEC "Rough
// dielectrics"). The view is seen from above (ggx_dielectric_side.hpp): a normal m drawn by the
// conductor sampler reflects with probability F(i.m) and refracts otherwise.
#include <cmath>

#include "ggx_dielectric.hpp"
#include "ggx_dielectric_side.hpp"

namespace ggxref {
namespace {

using detail::Side;

bool finite(const Sample& s)
{
    for (double v : {s.m.x, s.m.y, s.m.z, s.o.x, s.o.y, s.o.z, s.pdf_m, s.pdf_o, s.weight})
        if (!std::isfinite(v))
            return false;
    return true;
}

Sample invalid(Sample s)
{
    s.pdf_o = 0.0;
    s.weight = 0.0;
    return s;
}

// |d w_m / d w_o| of a refraction with c = i.m and o.m = -cos_t (SPEC: eta^2 |o.m| / (i.m + eta
// o.m)^2). Snell's law gives c^2 - eta^2 cos_t^2 = 1 - eta^2, so c - eta cos_t = (1 - eta^2) /
// (c + eta cos_t): no cancellation as eta nears 1.
double refraction_jacobian(double c, double cos_t, double eta)
{
    const double sum = c + eta * cos_t, d = 1.0 - eta * eta;
    return eta * eta * cos_t * sum * sum / (d * d);
}

// f |o.n| / pdf_o of a transmission through m (SPEC "Rough dielectrics"): G2 (i.m) / (iz mz) for NDF
// sampling (pdf_m = D mz), G2 / G1(i) = G2 (iz + t) / (2 iz) for the VNDF methods; radiance divides
// by eta^2. 0 for a view on the horizon, where the BTDF's 1 / iz has no value.
double transmission_weight(const Side& side, const Vec3& m, const Vec3& o, double c, bool radiance)
{
    const Vec3& i = side.p.i;
    const double iz = side.height(i);
    if (!(iz > 0.0))
        return 0.0;
    const double g2 = side.g2_even(i, o);
    const double w = side.method == Method::ndf ? g2 * c / (iz * side.height(m)) : g2 * (iz + side.t(i)) / (2.0 * iz);
    return radiance ? w / (side.eta * side.eta) : w;
}

// Refraction of the view through m (Walter et al. eq. 40): o = -i / eta + (c / eta - cos_t) m with
// cos_t = sqrt(1 - (1 - c^2) / eta^2), so that o.m = -cos_t. Valid when o crosses the surface.
Sample transmit(const Side& side, Sample s, double c, double F, bool radiance)
{
    const double eta = side.eta;
    const double cos_t = std::sqrt(std::fmax(0.0, 1.0 - (1.0 - c * c) / (eta * eta)));
    s.o = (-1.0 / eta) * side.p.i + (c / eta - cos_t) * s.m;
    if (!(side.height(s.o) < 0.0) || !(cos_t > 0.0))
        return invalid(s);
    s.pdf_o = (1.0 - F) * s.pdf_m * refraction_jacobian(c, cos_t, eta);
    s.weight = transmission_weight(side, s.m, s.o, c, radiance);
    return s;
}

// The lobe of the conductor sample s (a view from above, s.pdf_o > 0): u3 < F reflects (the
// conductor's o, pdf and weight with the probability F; its weight has no Fresnel, which cancels
// against the probability), else s refracts. A normal facing away from the view does neither.
Sample choose_lobe(const Side& side, const Sample& s, bool radiance, double u3)
{
    const double c = dot(side.p.i, s.m);
    if (!(c > 0.0))
        return invalid(s);
    const double F = fresnel_dielectric(c, side.eta);
    if (u3 < F) {
        if (!(side.height(s.o) > 0.0))
            return invalid(s);
        Sample r = s;
        r.pdf_o = F * s.pdf_o;
        return r;
    }
    return transmit(side, s, c, F, radiance);
}

}  // namespace

Sample dielectric_sample(Method method, const Params& p, double eta, bool radiance, double u1, double u2, double u3)
{
    const Vec3 n = detail::surface_normal(method, p);
    const Sample fallback{n, n, 0.0, 0.0, 0.0};
    if (method == Method::bounded || !detail::eta_ok(eta))
        return fallback;
    const Side side = detail::side_of(method, p, eta);
    Sample s = sample(method, side.p, u1, u2);
    if (s.pdf_o > 0.0)
        s = choose_lobe(side, s, radiance, u3);
    s.m = side.flip(s.m);
    s.o = side.flip(s.o);
    return finite(s) ? s : Sample{side.flip(n), side.flip(n), 0.0, 0.0, 0.0};
}

// Reflection on the view's side: the half vector h = normalize(i + o) faces up and i.h > 0, and the
// conductor's pdf_o times F(i.h). Across: the generalized half vector m = -(i + eta o) / |i + eta o|,
// turned to face up; |i.m + eta o.m| = |i + eta o|.
double dielectric_pdf_o(Method method, const Params& p, double eta, const Vec3& o)
{
    if (method == Method::bounded || !detail::eta_ok(eta))
        return 0.0;
    const Side side = detail::side_of(method, p, eta);
    const Vec3& i = side.p.i;
    const Vec3 oa = side.flip(o);
    const double oz = side.height(oa);
    if (oz > 0.0)
        return fresnel_dielectric(dot(i, normalize(i + oa)), side.eta) * pdf_o(method, side.p, oa);
    const Vec3 v = i + side.eta * oa;
    const double v2 = dot(v, v);
    if (!(oz < 0.0) || v2 == 0.0)
        return 0.0;
    const Vec3 m = (side.height(v) > 0.0 ? 1.0 : -1.0) * normalize(v);
    const double c = dot(i, m), om = dot(oa, m);
    if (!(c > 0.0 && om < 0.0))
        return 0.0;
    const double density = (1.0 - fresnel_dielectric(c, side.eta)) * pdf_m(method, side.p, m) * side.eta * side.eta *
                           -om / v2;
    return std::isfinite(density) ? density : 0.0;
}

}  // namespace ggxref
