// ggx_dielectric.cpp - the rough dielectric's BSDF value times |oz| in double
// precision (Walter et al. 2007, eqs. 20-21; SPEC "Rough dielectrics"):
// reflection with F(i.h), transmission through the generalized half vector
// with (1 - F(i.m)) and Smith's G2 with Lambda even in o.
#include <cmath>

#include "ggx_reference.hpp"

namespace ggxref {

namespace {

// Smith Lambda even in w: the value for the direction mirrored to the upper side.
double lambda_even(const Vec3& w, double ax, double ay)
{
    return lambda({w.x, w.y, std::fabs(w.z)}, ax, ay);
}

// The transmission value for i above (iz > 0) and o below, relative index eta, without Fresnel.
double transmission_above(const Vec3& i, const Vec3& o, double ax, double ay, double eta, bool radiance)
{
    Vec3 m = -1.0 * (i + eta * o);
    if (m.z < 0.0)
        m = -1.0 * m;
    if (length(m) == 0.0)
        return 0.0;
    m = normalize(m);
    const double im = dot(i, m), om = dot(o, m);
    if (im <= 0.0 || om >= 0.0)
        return 0.0;
    const double g2 = 1.0 / (1.0 + lambda_even(i, ax, ay) + lambda_even(o, ax, ay));
    const double jacobian_part = im * std::fabs(om) / std::pow(im + eta * om, 2.0);
    const double importance = D(m, ax, ay) * g2 * jacobian_part * eta * eta / i.z;
    return radiance ? importance / (eta * eta) : importance;
}

} // namespace

double btdf_cos(const Vec3& i, const Vec3& o, double ax, double ay, double eta, bool radiance)
{
    if (i.z * o.z >= 0.0)
        return 0.0;
    if (i.z < 0.0)
        return transmission_above({i.x, i.y, -i.z}, {o.x, o.y, -o.z}, ax, ay, 1.0 / eta, radiance);
    return transmission_above(i, o, ax, ay, eta, radiance);
}

double dielectric_cos(const Vec3& i, const Vec3& o, double ax, double ay, double eta, bool radiance)
{
    if (i.z == 0.0 || o.z == 0.0)
        return 0.0;
    const double side = i.z > 0.0 ? 1.0 : -1.0;
    const Vec3 iu{i.x, i.y, side * i.z}, ou{o.x, o.y, side * o.z};
    const double e = side > 0.0 ? eta : 1.0 / eta;
    if (ou.z > 0.0)
        return fresnel_dielectric(dot(iu, normalize(iu + ou)), e) * brdf_cos(iu, ou, ax, ay);
    Vec3 m = -1.0 * (iu + e * ou);
    if (m.z < 0.0)
        m = -1.0 * m;
    if (length(m) == 0.0)
        return 0.0;
    return (1.0 - fresnel_dielectric(dot(iu, normalize(m)), e)) * btdf_cos(iu, ou, ax, ay, e, radiance);
}

} // namespace ggxref
