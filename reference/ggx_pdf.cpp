// ggx_pdf.cpp - densities of every method, from the sampled m (as the sampler knows them) and
// recomputed from a direction alone, and the assembly of one Sample with its furnace weight.
#include <algorithm>
#include <cmath>

#include "ggx_reference.hpp"

namespace ggxref {
namespace {

double sq(double x) { return x * x; }

bool roughness_ok(const Params& p)
{
    return p.ax > 0.0 && p.ay > 0.0 && std::isfinite(p.ax) && std::isfinite(p.ay);
}

bool finite(const Sample& s)
{
    const double values[] = {s.m.x, s.m.y, s.m.z, s.o.x, s.o.y, s.o.z, s.pdf_m, s.pdf_o, s.weight};
    for (double v : values)
        if (!std::isfinite(v))
            return false;
    return true;
}

// The documented answer outside a method's domain (docs/STABILITY.md): m = o = n, pdfs and
// weight 0 ("no sample").
Sample fallback(Method method, const Params& p)
{
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0.0, 0.0, 1.0};
    return {n, n, 0.0, 0.0, 0.0};
}

double guarded(const Params& p, double pdf)
{
    return roughness_ok(p) && std::isfinite(pdf) ? pdf : 0.0;
}

// Every method but NDF sampling draws from a spherical cap (VNDF or bounded).
bool is_vndf_cap(Method method) { return method != Method::ndf; }

// What the densities need of the view: its height iz, t(i), and q = t^2 - iz^2 (stretched tangential part).
struct View {
    double iz, t, q;
};

View view_of(Method method, const Params& p)
{
    if (method == Method::caps_iso) {
        const Vec3 c = cross(p.i, p.n);
        return {dot(p.i, p.n), t_iso(p.i, p.n, p.ax), sq(p.ax) * dot(c, c)};
    }
    return {p.i.z, t_of(p.i, p.ax, p.ay), sq(p.ax * p.i.x) + sq(p.ay * p.i.y)};
}

// 1 / (k iz + t). Below the horizon the cap is the VNDF one (k = 1) and 1/(iz + t) = (t - iz)/q
// (bounded supplement, section 3).
double inv_norm(const View& v, double k) { return v.iz >= 0.0 ? 1.0 / (k * v.iz + v.t) : (v.t - v.iz) / v.q; }

// The cap factor k actually used: Eto-Tokuyoshi k for the bounded sampler above the horizon, else 1.
double k_eff(Method method, const Params& p)
{
    return method == Method::bounded && p.i.z > 0.0 ? bounded_k(p.i, p.ax, p.ay) : 1.0;
}

double height(Method method, const Params& p, const Vec3& w) { return method == Method::caps_iso ? dot(w, p.n) : w.z; }

double ndf(Method method, const Params& p, const Vec3& m)
{
    return method == Method::caps_iso ? D_iso(m, p.n, p.ax) : D(m, p.ax, p.ay);
}

// Eto-Tokuyoshi pdf support: the stretched reflection ohat of ih about mhat = normalize(M m) must
// lie in the cap ohat.z >= -k ih.z (supplement Sec. 2, chi+(k ih.z + ohat.z)).
bool in_bounded_cap(const Params& p, const Vec3& m)
{
    if (!(p.i.z > 0.0))
        return true;
    const Vec3 ih = normalize({p.ax * p.i.x, p.ay * p.i.y, p.i.z});
    const Vec3 mhat = normalize({m.x / p.ax, m.y / p.ay, m.z});
    return reflect(ih, mhat).z >= -bounded_k(p.i, p.ax, p.ay) * ih.z;
}

// pdf of m without the bounded-cap test: D mz for NDF sampling, 2 D max(0, i.m) / (k iz + t)
// otherwise (VNDF for k = 1; Eto-Tokuyoshi p_our(m) for the bounded cap).
double density_m(Method method, const Params& p, const Vec3& m)
{
    const double d = ndf(method, p, m);
    if (method == Method::ndf)
        return d * m.z;
    return 2.0 * d * std::max(0.0, dot(p.i, m)) * inv_norm(view_of(method, p), k_eff(method, p));
}

// pdf of o = reflect(i, m) given m: density_m / (4 |i.m|), simplified (docs/MATH.md) to
// D mz / (4 |i.m|) (NDF) and D / (2 (k iz + t)) (caps family).
double density_o(Method method, const Params& p, const Vec3& m)
{
    const double d = ndf(method, p, m);
    if (method == Method::ndf)
        return d * m.z / (4.0 * std::fabs(dot(p.i, m)));
    return 0.5 * d * inv_norm(view_of(method, p), k_eff(method, p));
}

}  // namespace

double pdf_m(Method method, const Params& p, const Vec3& m)
{
    if (!roughness_ok(p) || (method == Method::bounded && !in_bounded_cap(p, m)))
        return 0.0;
    return guarded(p, density_m(method, p, m));
}

// The half vector h = normalize(i + o) is the only normal reflecting i to o; NDF sampling may have
// drawn -h (then i.m < 0), the caps family only normals with h.z > 0.
double pdf_o(Method method, const Params& p, const Vec3& o)
{
    const Vec3 v = p.i + o;
    if (dot(v, v) == 0.0)
        return 0.0;
    const Vec3 h = normalize(v);
    const double hz = height(method, p, h);
    if (!roughness_ok(p))
        return 0.0;
    if (method == Method::ndf) {  // D mz / (4 |i.m|) with |i.m| = |i + o| / 2, well conditioned near o = -i
        const Vec3 m = hz > 0.0 ? h : -h;
        return hz == 0.0 ? 0.0 : guarded(p, D(m, p.ax, p.ay) * m.z / (2.0 * length(v)));
    }
    if (hz <= 0.0 || (method == Method::bounded && !in_bounded_cap(p, h)))
        return 0.0;
    return guarded(p, density_o(method, p, h));
}

namespace {

// Furnace weight w = D(m) G2(i, o) / (4 iz) / pdf_o for reflections above the horizon (docs/MATH.md).
Sample unguarded_sample(Method method, const Params& p, double u1, double u2)
{
    Sample s{};
    s.m = sample_normal(method, p, u1, u2);
    s.o = reflect(p.i, s.m);
    s.pdf_m = density_m(method, p, s.m);
    s.pdf_o = density_o(method, p, s.m);
    if (method == Method::ndf && dot(p.i, s.m) == 0.0)
        s.pdf_o = 0.0;  // a view across the surface reflected about m = n: o = -i has no density
    const double iz = height(method, p, p.i), oz = height(method, p, s.o);
    const bool valid = iz > 0.0 && oz > 0.0 && (is_vndf_cap(method) || dot(p.i, s.m) > 0.0);
    if (!valid)
        return s;
    const double g2 = method == Method::caps_iso ? G2_height_correlated_iso(p.i, s.o, p.n, p.ax)
                                                 : G2_height_correlated(p.i, s.o, p.ax, p.ay);
    s.weight = ndf(method, p, s.m) * g2 / (4.0 * iz) / s.pdf_o;
    return s;
}

// The domain rule the device applies too: the visible area (iz + t)/2 must exceed 5e-21 (the view
// exactly opposite the normal sees nothing) and caps-iso's half-turn needs 1 + nz > 1e-20.
bool sees_enough(Method method, const Params& p)
{
    if (method == Method::ndf)
        return true;
    const bool area_ok = inv_norm(view_of(method, p), 1.0) < 1e20;
    return method == Method::caps_iso ? area_ok && 1.0 / (1.0 + p.n.z) < 1e20 : area_ok;
}

}  // namespace

Sample sample(Method method, const Params& p, double u1, double u2)
{
    if (!roughness_ok(p) || !sees_enough(method, p))
        return fallback(method, p);
    Sample s = unguarded_sample(method, p, u1, u2);
    return finite(s) ? s : fallback(method, p);
}

}  // namespace ggxref
