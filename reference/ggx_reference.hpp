// ggx_reference.hpp - double-precision host reference of the ggxcl GGX samplers: the oracle the
// device kernels are tested against. Math and conventions: docs/MATH.md. Tangent space has
// n = (0, 0, 1); i and o point away from the surface; alpha is GGX alpha; u1, u2 lie in [0, 1).
#pragma once

#include <array>
#include <cstdint>

#include "ggx_contract.h"  // the project's one list of methods (names and ids; no math)
#include "ggx_vec.hpp"

namespace ggxref {

// ndf, heitz, heitz2017, caps, caps_iso, bounded: GGX_METHOD_LIST of kernels/ggx_contract.h,
// with its ids, in id order.
enum class Method { GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR) };
#define GGX_METHOD_ENUM Method
constexpr std::array<Method, GGX_METHOD_COUNT> all_methods = {GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR_OF)};
#undef GGX_METHOD_ENUM
const char* method_name(Method);  // "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"

struct Params {
    double ax, ay;    // GGX alpha (caps_iso uses ax only, must equal ay)
    Vec3 i;           // unit view direction (tangent space; world space for caps_iso)
    Vec3 n{0, 0, 1};  // surface normal, world space, only caps_iso reads it
};

struct Sample {
    Vec3 m, o;            // microfacet normal and reflected direction
    double pdf_m, pdf_o;  // densities per steradian, computed from m as the sampler knows it
    double weight;        // D(m) G2(i,o) / (4 iz) / pdf_o, 0 when iz <= 0 or oz <= 0 (white furnace)
};

// Outside a method's domain (a roughness not finite and > 0; a visible area (iz + t)/2 of 5e-21 or
// less; caps-iso with 1 + nz <= 1e-20; any result not finite) sample() returns the fallback
// m = o = n, pdfs and weight 0, and the pdfs are 0 (docs/STABILITY.md), as the device does.
Sample sample(Method, const Params&, double u1, double u2);       // one sample from two uniforms
Vec3 sample_normal(Method, const Params&, double u1, double u2);  // its microfacet normal m only
double pdf_o(Method, const Params&, const Vec3& o);               // pdf of o recomputed from (i, o) alone
double pdf_m(Method, const Params&, const Vec3& m);               // pdf of m recomputed from (i, m) alone

// GGX math, tangent space, anisotropic (docs/MATH.md "Shared quantities").
double t_of(const Vec3& w, double ax, double ay);    // sqrt(ax^2 wx^2 + ay^2 wy^2 + wz^2)
double D(const Vec3& m, double ax, double ay);       // 0 for mz <= 0
double lambda(const Vec3& w, double ax, double ay);  // Smith Lambda, Lambda(-w) = 1 + Lambda(w)
double G1(const Vec3& w, double ax, double ay);      // 0 for wz <= 0
double G2_height_correlated(const Vec3& i, const Vec3& o, double ax, double ay);  // 0 unless iz, oz > 0
double G2_separable(const Vec3& i, const Vec3& o, double ax, double ay);          // G1(i) G1(o)
double projected_area(const Vec3& i, double ax, double ay);           // (iz + t)/2, cancellation-free for iz < 0
double vndf_pdf(const Vec3& m, const Vec3& i, double ax, double ay);  // Dv(m; i)
double bounded_k(const Vec3& i, double ax, double ay);                // Eto-Tokuyoshi k, k < 0 for a > 1
double brdf_cos(const Vec3& i, const Vec3& o, double ax, double ay);  // D(h) G2hc / (4 iz), 0 unless iz, oz > 0

// Fresnel reflectance at c = cos of the angle of incidence (docs/MATH.md "Fresnel and roughness"),
// computed with complex amplitudes (ggx_fresnel.cpp), independently of the device's real forms.
double fresnel_dielectric(double c, double eta);       // relative index eta; c < 0: from the other side
double fresnel_conductor(double c, double eta, double k);  // complex index eta + i k, c in [0, 1]
double fresnel_schlick(double c, double f0);

// A rough dielectric of relative index eta (below over above), f |oz| (ggx_dielectric.cpp): the BTDF
// without Fresnel (0 unless i and o lie on opposite sides), and the whole BSDF with its Fresnel; a
// view below sees the interface from the other side. radiance: divided by eta^2 (importance: not).
double btdf_cos(const Vec3& i, const Vec3& o, double ax, double ay, double eta, bool radiance);
double dielectric_cos(const Vec3& i, const Vec3& o, double ax, double ay, double eta, bool radiance);

// The same for an isotropic surface with world-space normal n (caps_iso): z components are dot
// products with n, t(w) = sqrt(alpha^2 |w x n|^2 + (w.n)^2).
double D_iso(const Vec3& m, const Vec3& n, double alpha);
double t_iso(const Vec3& w, const Vec3& n, double alpha);
double G2_height_correlated_iso(const Vec3& i, const Vec3& o, const Vec3& n, double alpha);

// Uniforms: Random123 Philox2x32-10, key = seed, counter = {index lo, index hi};
// u1 = (w0 >> 8) 2^-24, u2 = (w1 >> 8) 2^-24.  Seeds are 32-bit (the library refuses larger
// ones); uniforms() uses the low 32 bits of its seed.
std::array<uint32_t, 2> philox2x32_10(const std::array<uint32_t, 2>& counter, uint32_t key);
std::array<uint32_t, 2> philox_words(uint32_t seed, uint64_t index);
// The Owen-scrambled Sobol points of kernels/ggx_sobol.h: the first two Sobol dimensions of point k
// (unscrambled, as 32-bit binary fractions), the keyed nested uniform scramble, and the two words of
// sample `index` of stream `seed` (u = top 24 bits times 2^-24).
std::array<uint32_t, 2> sobol_points(uint32_t k);
uint32_t owen_scramble(uint32_t word, uint32_t key);
std::array<uint32_t, 2> sobol_words(uint32_t seed, uint64_t index);
std::array<double, 2> uniforms(uint64_t seed, uint64_t index);        // Philox
std::array<double, 2> sobol_uniforms(uint64_t seed, uint64_t index);  // the scrambled Sobol points
// A dielectric's third uniform u3 (the lobe choice; kernels/ggx_sobol.h, ggx_philox.h): Sobol's third
// dimension (primitive polynomial x^2 + x + 1, m_1 = 1, m_2 = 3) of point k = index mod 2^32: its 32
// direction numbers v_1 .. v_32 as 32-bit fractions, the unscrambled point, and the point scrambled
// as the first two with the key of dimension 2; or word 0 of Philox2x32-10 with key = seed and
// counter (index lo, index hi xor 2^31). u3 = top 24 bits times 2^-24.
std::array<uint32_t, 32> sobol_third_directions();
uint32_t sobol_third_point(uint32_t k);
uint32_t sobol_third_word(uint32_t seed, uint64_t index);
double lobe_uniform_sobol(uint64_t seed, uint64_t index);
double lobe_uniform_philox(uint64_t seed, uint64_t index);

}  // namespace ggxref

#include "ggx_dielectric.hpp"  // the rough dielectric: sampling, densities, bins, furnace
