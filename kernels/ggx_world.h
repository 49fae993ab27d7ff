// ggx_world.h - sampling in world space: every method takes the world-space
// normal n and view i and returns m and o in world space.  The tangent-space
// methods build an orthonormal basis around n (Duff et al. 2017, "Building
// an Orthonormal Basis, Revisited", JCGT 6(1), Listing 3: branchless, exact
// for n = -z too) and transform i in and m, o out; caps-iso needs no basis.
// World space is isotropic: a basis from n alone has no tangent direction.
#ifndef GGX_WORLD_H
#define GGX_WORLD_H

#include "ggx_dielectric.h"

struct ggx_basis {
    ggx_vec3 t, b, n;
};
GGX_TYPEDEF_STRUCT(ggx_basis)

// Duff et al. 2017, Listing 3: side = ggx_copysign(1, nz), a = -1/(side + nz), b = nx ny a,
// t = (1 + side nx^2 a, side b, -side nx), b = (b, side + ny^2 a, -ny).
GGX_INLINE ggx_basis ggx_basis_from_normal(ggx_vec3 n)
{
    ggx_real side = ggx_copysign(GGX_R(1.0f), n.z);
    ggx_real a = -GGX_R(1.0f) / (side + n.z);
    ggx_real b = n.x * n.y * a;
    ggx_basis basis;
    basis.t = ggx_vec3_make(GGX_R(1.0f) + side * n.x * n.x * a, side * b, -side * n.x);
    basis.b = ggx_vec3_make(b, side + n.y * n.y * a, -n.y);
    basis.n = n;
    return basis;
}

GGX_INLINE ggx_vec3 ggx_to_local(ggx_basis basis, ggx_vec3 v)
{
    return ggx_vec3_make(ggx_dot(v, basis.t), ggx_dot(v, basis.b), ggx_dot(v, basis.n));
}

GGX_INLINE ggx_vec3 ggx_from_local(ggx_basis basis, ggx_vec3 v)
{
    return ggx_add(ggx_add(ggx_scale(basis.t, v.x), ggx_scale(basis.b, v.y)), ggx_scale(basis.n, v.z));
}

// A sample of `method` for world-space n and i with roughness alpha; m and o in world space.
GGX_INLINE ggx_sample ggx_sample_world(int method, ggx_vec3 n, ggx_vec3 i, ggx_real alpha, ggx_real u1, ggx_real u2)
{
    if (ggx_method_world_space(method) != 0)
        return ggx_sample_method(method, n, i, alpha, alpha, u1, u2);
    ggx_basis basis = ggx_basis_from_normal(n);
    ggx_sample s = ggx_sample_method(method, n, ggx_to_local(basis, i), alpha, alpha, u1, u2);
    s.m = ggx_from_local(basis, s.m);
    s.o = ggx_from_local(basis, s.o);
    return s;
}

// The BRDF value f |cos| (ggx_eval_reflection) of world-space i and o about the normal n.
GGX_INLINE ggx_real ggx_eval_reflection_world(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real alpha)
{
    ggx_basis basis = ggx_basis_from_normal(n);
    return ggx_eval_reflection(ggx_to_local(basis, i), ggx_to_local(basis, o), alpha, alpha);
}

// The pdf of the world-space direction o for `method` (0 where it never samples o).
GGX_INLINE ggx_real ggx_pdf_world(int method, ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real alpha)
{
    if (ggx_method_world_space(method) != 0)
        return ggx_pdf_method(method, n, i, o, alpha, alpha);
    ggx_basis basis = ggx_basis_from_normal(n);
    return ggx_pdf_method(method, n, ggx_to_local(basis, i), ggx_to_local(basis, o), alpha, alpha);
}

// The dielectric value f |cos| (ggx_eval_dielectric) of world-space i and o about the normal n.
GGX_INLINE ggx_real ggx_eval_dielectric_world(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real alpha, ggx_real eta,
                                             int radiance)
{
    ggx_basis basis = ggx_basis_from_normal(n);
    return ggx_eval_dielectric(ggx_to_local(basis, i), ggx_to_local(basis, o), alpha, alpha, eta, radiance);
}

// A dielectric sample of `method` (ggx_dielectric.h) for world-space n and i; m and o in world space.
GGX_INLINE ggx_sample ggx_sample_dielectric_world(int method, ggx_vec3 n, ggx_vec3 i, ggx_real alpha, ggx_real eta,
                                                  int radiance, ggx_real u1, ggx_real u2, ggx_real u3)
{
    const bool below = ggx_dot(i, n) < GGX_R(0.0f);
    if (ggx_method_dielectric(method) == 0)
        return ggx_fallback_sample(n);
    const ggx_vec3 i_above = ggx_mirror_if(i, n, below);
    ggx_sample s = ggx_sample_world(method, n, i_above, alpha, u1, u2);
    s = ggx_dielectric_from_reflection(s, n, i_above, alpha, alpha, below ? GGX_R(1.0f) / eta : eta, radiance, u3,
                                       ggx_method_ndf_normals(method) != 0, true);
    s.m = ggx_mirror_if(s.m, n, below);
    s.o = ggx_mirror_if(s.o, n, below);
    return ggx_keep_or_fallback(s, ggx_eta_ok(eta), ggx_mirror_if(n, n, below));
}

// The density of the world-space o for `method`'s dielectric sampler, from (i, o) alone.
GGX_INLINE ggx_real ggx_pdf_dielectric_world(int method, ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real alpha,
                                            ggx_real eta)
{
    const bool below = ggx_dot(i, n) < GGX_R(0.0f);
    if (ggx_method_dielectric(method) == 0)
        return GGX_R(0.0f);
    const ggx_vec3 i_above = ggx_mirror_if(i, n, below), o_side = ggx_mirror_if(o, n, below);
    const ggx_real eta_side = below ? GGX_R(1.0f) / eta : eta;
    const ggx_real reflection_pdf = ggx_pdf_world(method, n, i_above, o_side, alpha);
    const ggx_real pdf =
        ggx_dielectric_pdf_above(method, n, i_above, o_side, alpha, alpha, eta_side, reflection_pdf, true);
    return ggx_guard_pdf(ggx_eta_ok(eta) != 0 ? pdf : GGX_R(0.0f), alpha, alpha);
}

#endif
