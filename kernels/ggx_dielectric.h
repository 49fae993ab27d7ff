// ggx_dielectric.h - rough dielectrics (Walter et al. 2007) with every
// sampler of normals: a sampled m reflects the view with probability
// F(i.m), the exact dielectric Fresnel, and refracts it otherwise.
//   ggx_sample_dielectric_method(method, n, i, ax, ay, eta, radiance, u1, u2, u3)
//   ggx_pdf_dielectric_method(method, n, i, o, ax, ay, eta)
// (tangent space; n is read by caps-iso) and their world-space forms in
// ggx_world.h.  eta: index below the surface over index above, > 0 and
// != 1; radiance = 1 for radiance transport (a transmission's weight divided
// by eta^2), 0 for importance.  u3 chooses the lobe.  A sample's o is the
// direction drawn, reflected or transmitted; pdf_o its density over the
// whole sphere with the lobe's probability (F p_r(o) or (1 - F) p_t(o));
// weight = f |o.n| / pdf_o; pdf_m the method's density of m.  An invalid
// sample (i.m <= 0, or o on the wrong side) has pdf_o = weight = 0.  An eta
// that is not finite, > 0 and != 1 gives the fallback and pdf 0.
// A view below the surface (i.n < 0) sees the interface from the other side:
// the frame is mirrored through the surface (i -> i - 2 (i.n) n), eta becomes
// 1/eta, and m and o are mirrored back (m then faces the view's side, and
// the fallback sample is m = o = the normal on the view's side).
// bounded has no exact dielectric form (its cap omits normals that refract
// fine: docs/MATH.md "Rough dielectrics"): it gives the fallback sample and
// pdf 0.  docs/MATH.md states the math.
#ifndef GGX_DIELECTRIC_H
#define GGX_DIELECTRIC_H

#include "ggx_samplers.h"

// A relative index the functions below take: finite, > 0 and != 1 (others
// give the fallback sample, pdf 0).
GGX_INLINE int ggx_eta_ok(ggx_real eta)
{
    return ggx_to_int(eta > GGX_R(0.0f)) & ggx_to_int(eta <= GGX_FLT_MAX) & ggx_to_int(eta != GGX_R(1.0f));
}

// v mirrored through the plane of the unit normal n, v - 2 (v.n) n, where
// `mirror` is set; v itself otherwise.  A scale, not a select of structs:
// struct selects stop PoCL's vectorizer (ggx_guards.h).
GGX_INLINE ggx_vec3 ggx_mirror_if(ggx_vec3 v, ggx_vec3 n, bool mirror)
{
    return ggx_add(v, ggx_scale(n, mirror ? -GGX_R(2.0f) * ggx_dot(v, n) : GGX_R(0.0f)));
}

// Per component: a where `pick_a`, else b.
GGX_INLINE ggx_vec3 ggx_select3(bool pick_a, ggx_vec3 a, ggx_vec3 b)
{
    return ggx_vec3_make(pick_a ? a.x : b.x, pick_a ? a.y : b.y, pick_a ? a.z : b.z);
}

// The unit w in the local coordinates the roughness functions take: w itself
// in tangent space (n = z), or, for an isotropic surface about a world-space n
// (about_n true), (|w_t|, 0, w.n): D and Lambda depend on nothing else there.
GGX_INLINE ggx_vec3 ggx_local_of(ggx_vec3 w, ggx_vec3 n, bool about_n)
{
    if (!about_n)
        return w;
    const ggx_real wn = ggx_dot(w, n);
    return ggx_vec3_make(ggx_sqrt(ggx_tangential2(w, n, wn)), GGX_R(0.0f), wn);
}

// Snell's law through m for c = i.m > 0 below the critical angle: with
// d = (eta - 1)(eta + 1), cos_t = sqrt(d + c^2) / eta (the form of
// ggx_fresnel_dielectric, without cancellation) and
// o = -i / eta + (c / eta - cos_t) m, so o.m = -cos_t (Walter et al. eq. 40).
// Normalized: for a small eta the rounding of i grows by 1/eta.
GGX_INLINE ggx_vec3 ggx_refract(ggx_vec3 i, ggx_vec3 m, ggx_real c, ggx_real eta, ggx_real cos_t)
{
    const ggx_real inv_eta = GGX_R(1.0f) / eta;
    return ggx_normalize(ggx_add(ggx_scale(i, -inv_eta), ggx_scale(m, c * inv_eta - cos_t)));
}

GGX_INLINE ggx_real ggx_refracted_cosine(ggx_real c, ggx_real eta)
{
    const ggx_real d = (eta - GGX_R(1.0f)) * (eta + GGX_R(1.0f));
    return ggx_sqrt(ggx_fmax(d + c * c, GGX_R(0.0f))) / eta;
}

// The Jacobian |dm/do| of a refraction, eta^2 |o.m| / (i.m + eta o.m)^2 with
// o.m = -cos_t, written without the cancellation of c - eta cos_t near
// eta = 1: c - eta cos_t = -d / (c + eta cos_t), so the Jacobian is
// cos_t q^2 with q = eta (c + eta cos_t) / d, a form that stays in float
// range for any index of a finite square.
GGX_INLINE ggx_real ggx_refraction_jacobian(ggx_real c, ggx_real eta, ggx_real cos_t)
{
    const ggx_real d = (eta - GGX_R(1.0f)) * (eta + GGX_R(1.0f));
    const ggx_real q = eta * ((c + eta * cos_t) / d);
    return cos_t * q * q;
}

// The density of the normal m for the method's family: D(m) mz for ndf
// (Walter et al. eq. 24), the VNDF 2 (i.m) D(m) / (iz + t(i)) otherwise
// (Heitz 2018 eq. 1); i_local, m_local as ggx_local_of gives, c = i.m > 0.
GGX_INLINE ggx_real ggx_normal_density(bool ndf, ggx_vec3 i_local, ggx_vec3 m_local, ggx_real c, ggx_real ax,
                                       ggx_real ay)
{
    const ggx_real D = ggx_D(m_local, ax, ay);
    if (ndf)
        return D * m_local.z;
    const ggx_real inv = ggx_inv_iz_plus_t(i_local.z, ggx_t(i_local, ax, ay), ax, ay, i_local);
    return GGX_R(2.0f) * c * D * inv;
}

// f |o.n| / pdf_o of a transmission through m (Walter et al. eqs. 21, 38-41;
// SPEC "Rough dielectrics"), the even Lambda for o below: G2 (i.m) / (iz mz)
// for ndf, G2 / G1(i) for the VNDF methods; radiance divides by eta^2.
GGX_INLINE ggx_real ggx_transmission_weight(bool ndf, ggx_vec3 i_local, ggx_vec3 o_local, ggx_vec3 m_local, ggx_real c,
                                         ggx_real ax, ggx_real ay, ggx_real eta, int radiance)
{
    const ggx_vec3 o_up = ggx_vec3_make(o_local.x, o_local.y, -o_local.z);
    const ggx_real iz = i_local.z, ti = ggx_t(i_local, ax, ay);
    const ggx_real g2 = ggx_G2_from_t(iz, o_up.z, ti, ggx_t(o_up, ax, ay));
    const ggx_real weight = ndf ? g2 * c / (iz * m_local.z) : g2 * (iz + ti) / (GGX_R(2.0f) * iz);
    const ggx_real scaled = radiance != 0 ? weight / (eta * eta) : weight;
    return iz > GGX_R(0.0f) ? scaled : GGX_R(0.0f);
}

// The dielectric sample from the reflection sample s of a view i above the
// surface (i.n >= 0; the sampler's m, pdf_m, reflected o, its pdf and weight).
// The lobe is a branch: computing both and selecting holds too much live at
// once for an unrolled furnace on RDNA3, which then spills.  s with pdf_o = 0
// (the fallback, or a direction without density) keeps its m and o.
GGX_INLINE ggx_sample ggx_dielectric_from_reflection(ggx_sample s, ggx_vec3 n, ggx_vec3 i, ggx_real ax, ggx_real ay,
                                                     ggx_real eta, int radiance, ggx_real u3, bool ndf, bool about_n)
{
    const ggx_real c = ggx_dot(i, s.m);
    const ggx_real F = ggx_fresnel_dielectric(ggx_fmax(c, GGX_R(0.0f)), eta);
    ggx_sample result = s;
    // A back-facing m (ndf) scatters nothing; o stays the fallback's.
    if (!(c > GGX_R(0.0f) && s.pdf_o > GGX_R(0.0f))) {
        result.pdf_o = GGX_R(0.0f);
        result.weight = GGX_R(0.0f);
        return result;
    }
    if (u3 < F) {  // reflection, with probability F (always under total internal reflection)
        const bool valid = ggx_dot(s.o, n) > GGX_R(0.0f);  // a reflection stays on the view's side
        result.pdf_o = valid ? F * s.pdf_o : GGX_R(0.0f);
        result.weight = valid ? s.weight : GGX_R(0.0f);
        return result;
    }
    // The transmission through m (Snell's law), its density and weight.
    const ggx_real cos_t = ggx_refracted_cosine(c, eta);
    result.o = ggx_refract(i, s.m, c, eta, cos_t);
    const bool valid = ggx_dot(result.o, n) < GGX_R(0.0f);  // a transmission crosses the surface
    const ggx_real weight =
        ggx_transmission_weight(ndf, ggx_local_of(i, n, about_n), ggx_local_of(result.o, n, about_n),
                                ggx_local_of(s.m, n, about_n), c, ax, ay, eta, radiance);
    result.pdf_o = valid ? (GGX_R(1.0f) - F) * s.pdf_m * ggx_refraction_jacobian(c, eta, cos_t) : GGX_R(0.0f);
    result.weight = valid ? weight : GGX_R(0.0f);
    return result;
}

// The density of o for a view i above the surface (i.n >= 0), both lobes:
// F(i.h) times the method's reflection pdf for o above; for o below, the
// generalized half vector m = -(i + eta o) turned to face n, valid where
// i.m > 0 and o.m < 0, with (1 - F(i.m)) pdf_m(m) |dm/do|.
GGX_INLINE ggx_real ggx_dielectric_pdf_above(int method, ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay,
                                          ggx_real eta, ggx_real reflection_pdf, bool about_n)
{
    const ggx_real on = ggx_dot(o, n);
    const ggx_real reflected =
        ggx_fresnel_dielectric(ggx_fmax(ggx_dot(i, ggx_half_vector(i, o)), GGX_R(0.0f)), eta) * reflection_pdf;
    ggx_vec3 m = ggx_add(i, ggx_scale(o, eta));
    const ggx_real len2 = ggx_dot(m, m);
    m = ggx_scale(m, (ggx_dot(m, n) > GGX_R(0.0f) ? GGX_R(1.0f) : -GGX_R(1.0f)) *
                         (len2 > GGX_R(0.0f) ? ggx_rsqrt(len2) : GGX_R(0.0f)));
    const ggx_real c = ggx_dot(i, m), om = ggx_dot(o, m);
    const int valid = ggx_to_int(on < GGX_R(0.0f)) & ggx_to_int(c > GGX_R(0.0f)) & ggx_to_int(om < GGX_R(0.0f));
    const ggx_real c_up = ggx_fmax(c, GGX_R(0.0f)), cos_t = ggx_fmax(-om, GGX_R(0.0f)), sum = c + eta * om;
    const ggx_real density = ggx_normal_density(ggx_method_ndf_normals(method) != 0, ggx_local_of(i, n, about_n),
                                              ggx_local_of(m, n, about_n), c_up, ax, ay);
    const ggx_real transmitted =
        (GGX_R(1.0f) - ggx_fresnel_dielectric(c_up, eta)) * density * eta * eta * cos_t / (sum * sum);
    return on > GGX_R(0.0f) ? reflected : (valid != 0 ? transmitted : GGX_R(0.0f));
}

// A dielectric sample of `method` in tangent space (caps-iso: about n).
GGX_INLINE ggx_sample ggx_sample_dielectric_method(int method, ggx_vec3 n, ggx_vec3 i, ggx_real ax, ggx_real ay,
                                                   ggx_real eta, int radiance, ggx_real u1, ggx_real u2, ggx_real u3)
{
    const bool about_n = ggx_method_world_space(method) != 0;
    const ggx_vec3 up = about_n ? n : ggx_vec3_make(GGX_R(0.0f), GGX_R(0.0f), GGX_R(1.0f));
    const bool below = ggx_dot(i, up) < GGX_R(0.0f);
    if (ggx_method_dielectric(method) == 0)
        return ggx_fallback_sample(up);
    const ggx_vec3 i_above = ggx_mirror_if(i, up, below);
    const ggx_real eta_side = below ? GGX_R(1.0f) / eta : eta;
    ggx_sample s = ggx_sample_method(method, n, i_above, ax, ay, u1, u2);
    s = ggx_dielectric_from_reflection(s, up, i_above, ax, ay, eta_side, radiance, u3,
                                       ggx_method_ndf_normals(method) != 0, about_n);
    s.m = ggx_mirror_if(s.m, up, below);
    s.o = ggx_mirror_if(s.o, up, below);
    return ggx_keep_or_fallback(s, ggx_eta_ok(eta), ggx_mirror_if(up, up, below));
}

// The density of o for `method`'s dielectric sampler, recomputed from (i, o) alone.
GGX_INLINE ggx_real ggx_pdf_dielectric_method(int method, ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay,
                                           ggx_real eta)
{
    const bool about_n = ggx_method_world_space(method) != 0;
    const ggx_vec3 up = about_n ? n : ggx_vec3_make(GGX_R(0.0f), GGX_R(0.0f), GGX_R(1.0f));
    const bool below = ggx_dot(i, up) < GGX_R(0.0f);
    if (ggx_method_dielectric(method) == 0)
        return GGX_R(0.0f);
    const ggx_vec3 i_above = ggx_mirror_if(i, up, below), o_side = ggx_mirror_if(o, up, below);
    const ggx_real eta_side = below ? GGX_R(1.0f) / eta : eta;
    const ggx_real reflection_pdf = ggx_pdf_method(method, n, i_above, o_side, ax, ay);
    const ggx_real pdf =
        ggx_dielectric_pdf_above(method, up, i_above, o_side, ax, ay, eta_side, reflection_pdf, about_n);
    return ggx_guard_pdf(ggx_eta_ok(eta) != 0 ? pdf : GGX_R(0.0f), ax, ay);
}

#endif
