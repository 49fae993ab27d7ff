// ggx_fresnel.cpp - Fresnel reflectance from the complex amplitude
// coefficients of the s and p polarizations, in double precision: Snell's
// law with a complex relative index n = eta + i k gives n ct =
// sqrt(n^2 - sin^2) (ct the refracted cosine; the principal root, the wave
// that decays into the conductor), then rs = (c - n ct) / (c + n ct),
// rp = (n^2 c - n ct) / (n^2 c + n ct), F = (|rs|^2 + |rp|^2) / 2.
// A dielectric is k = 0, where n ct turns imaginary past the critical
// angle and |rs| = |rp| = 1 (total internal reflection) follows by itself.
#include <algorithm>
#include <cmath>
#include <complex>

#include "ggx_reference.hpp"

namespace ggxref {

namespace {

using Complex = std::complex<double>;

double reflectance(double c, Complex n)
{
    const Complex n_ct = std::sqrt(n * n - (1.0 - c * c));
    const Complex rs = (c - n_ct) / (c + n_ct);
    const Complex rp = (n * n * c - n_ct) / (n * n * c + n_ct);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

} // namespace

double fresnel_dielectric(double c, double eta)
{
    if (c < 0.0)  // from the other side: |c| and 1/eta
        return reflectance(std::min(-c, 1.0), Complex(1.0 / eta, 0.0));
    return reflectance(std::min(c, 1.0), Complex(eta, 0.0));
}

double fresnel_conductor(double c, double eta, double k)
{
    return reflectance(std::clamp(c, 0.0, 1.0), Complex(eta, k));
}

double fresnel_schlick(double c, double f0)
{
    return f0 + (1.0 - f0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), 5.0);
}

} // namespace ggxref
