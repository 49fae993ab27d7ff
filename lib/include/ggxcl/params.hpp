// params.hpp - what a batch of samples depends on: the method, roughness,
// view (and normal for caps-iso), either uniform for the whole batch or per
// sample, and the range of sample indices of a seed.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ggxcl/method.hpp"
#include "ggxcl/user_sampler.hpp"

namespace ggxcl {

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 1.0f;
};

// The roughness a request may hold, each of alpha_x and alpha_y: what a float
// holds with room to spare (a smaller value, 9e-69 say, rounds to 0 on its
// way from a double).  The kernels guard values outside it (the fallback of
// docs/STABILITY.md); the library refuses them.
inline constexpr float min_alpha = 1e-30f, max_alpha = 1e30f;
inline constexpr const char* alpha_range = "a number from 1e-30 to 1e30";

// How the kernels compute (build options of the program, precision_options
// in ggxcl/user_kernels.hpp):
//   precise - no fast-math option, and the sampling angle's sine and cosine
//             within 0.86 ulp over the whole 24-bit grid of uniforms
//             (kernels/ggx_sincos.h); vectorizes on CPUs.  Division and
//             sqrt are correctly rounded (IEEE) where the device reports
//             CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT in CL_DEVICE_SINGLE_FP_CONFIG:
//             the program is built with -cl-fp32-correctly-rounded-divide-sqrt
//             there.  Elsewhere they have OpenCL's default accuracy:
//             division within 2.5 ulp, sqrt within 3 ulp;
//   relaxed - the same math built with -cl-fast-relaxed-math (and never
//             with the correctly rounded option).
enum class Precision { precise = 0, relaxed = 1 };
inline constexpr std::array<Precision, 2> all_precisions = {Precision::precise, Precision::relaxed};

std::string_view precision_name(Precision precision);   // "precise", "relaxed"
Precision parse_precision(std::string_view name);       // throws InvalidArgument naming the modes
std::string precision_list();                           // "precise, relaxed", for messages

// Where the two uniforms of sample k of stream `seed` come from (both give
// u1, u2 on the grid of 2^-24 in [0, 1), and sample k depends on (seed, k)
// alone, so chunks, shards and device splits give the same bits):
//   philox - Philox2x32-10 with key seed and counter k: independent numbers;
//   sobol  - point k of the first two Sobol dimensions, Owen-scrambled by a
//            hash keyed by seed (Burley 2020): the first 2^m points of a
//            stream (first = 0) put one point in every elementary interval
//            of area 2^-m, so estimates converge faster than with philox.
// The caller's own uniforms (PerSampleInputs::uniforms,
// DeviceInputs::uniforms) replace either.  docs/MATH.md "Uniforms".
enum class Sequence { philox = 0, sobol = 1 };
inline constexpr std::array<Sequence, 2> all_sequences = {Sequence::philox, Sequence::sobol};

std::string_view sequence_name(Sequence sequence);  // "philox", "sobol"
Sequence parse_sequence(std::string_view name);     // throws InvalidArgument naming the sequences
std::string sequence_description(Sequence sequence);  // how its uniforms are made, for sidecars

// How a rough dielectric's transmission is weighted (SampleParams::eta):
//   radiance   - the BTDF of light carried from lights to the eye, divided
//                by eta'^2 as it enters a medium of relative index eta'
//                (pbrt-v4's TransportMode::Radiance): what a path tracer uses;
//   importance - the adjoint, without that factor (light tracing, photons);
//                its white furnace is the energy the interface conserves.
enum class Transport { radiance = 0, importance = 1 };
inline constexpr std::array<Transport, 2> all_transports = {Transport::radiance, Transport::importance};

std::string_view transport_name(Transport transport);  // "radiance", "importance"
Transport parse_transport(std::string_view name);      // throws InvalidArgument naming both

// Parameters shared by every sample of a batch.
struct SampleParams {
    Method method = Method::caps;
    float alpha_x = 0.3f, alpha_y = 0.3f;  // GGX alpha > 0; caps-iso needs alpha_x == alpha_y
    Vec3 view{0.0f, 0.0f, 1.0f};           // unit, pointing away from the surface; tangent space
                                           // (world space for caps-iso); z < 0 is below the horizon
    Vec3 normal{0.0f, 0.0f, 1.0f};         // caps-iso and world space: the world-space surface normal
    Precision precision = Precision::precise;
    Sequence sequence = Sequence::philox;  // where the uniforms come from (see Sequence)
    // World space for every method: view, normal and the returned m and o are
    // world-space vectors.  The tangent-space methods build a basis around the
    // normal (Duff et al. 2017) and transform in and out; caps-iso needs none.
    // Isotropic only (alpha_x == alpha_y): the normal alone fixes no tangent.
    bool world_space = false;
    // A rough dielectric instead of a mirror-like conductor: eta = 0 (the
    // default) reflects with Fresnel 1; eta > 0, eta != 1 is the index below
    // the surface over the index above.  Each sample then reflects with
    // probability F(i.m) (the exact dielectric Fresnel) and refracts
    // otherwise, drawing a third uniform for the choice; o is the direction
    // drawn, pdf_o its density over the whole sphere with the lobe's
    // probability, weight f |cos| / pdf_o in `transport`.  A view below the
    // surface sees it from the other side (index 1/eta).  Every method but
    // bounded (whose cap omits normals that refract: docs/MATH.md).
    float eta = 0.0f;
    Transport transport = Transport::radiance;
    // The sampler of Method::user (set both, or neither): a file of the user's own
    // (ggxcl/user_sampler.hpp), in tangent space, on a conductor (eta = 0).
    std::shared_ptr<const UserSampler> user_sampler;
    // Outside its domain (a roughness of 0, the view exactly opposite the
    // normal, ...) every method returns the fallback m = o = n, pdfs and
    // weight 0 (docs/STABILITY.md).  false: the kernels without these
    // guards, for measuring what they cost (`ggx bench`); outside a method's
    // domain NaN and Inf are then possible.  Inside it the bits are the same.
    bool guards = true;
};

// The name of params' sampler in reports: the user sampler's name for Method::user, else
// method_name(params.method).
std::string sampler_name(const SampleParams& params);

// Whether the view is measured against params.normal (caps-iso, world space)
// rather than the tangent-space +z.
bool uses_normal(const SampleParams& params);

// Samples first .. first+count-1 of the stream `seed`.  Sample k depends on
// (seed, k) alone, so any split into ranges gives the same values: its
// uniforms are point k of SampleParams::sequence (with Philox, the two words
// of Philox2x32-10 with key seed and counter k, u1 from word 0, u2 from
// word 1, each its top 24 bits times 2^-24).  Seeds are 0 .. max_seed (the
// generators' key is one 32-bit word).
inline constexpr std::uint64_t max_seed = 0xffffffffull;
inline constexpr const char* seed_range = "0 .. 2^32 - 1";  // what errors and help say of it
struct SampleRange {
    std::uint64_t seed = 0;
    std::uint64_t first = 0;
    std::uint64_t count = 0;
};

// Per-sample parameters held on the host; an empty vector means "use the
// uniform value of SampleParams" (for uniforms: its sequence).  A non-empty
// vector has one entry per sample.
struct PerSampleInputs {
    std::vector<Vec3> views;
    std::vector<std::array<float, 2>> alphas;    // (alpha_x, alpha_y)
    std::vector<Vec3> normals;
    std::vector<std::array<float, 2>> uniforms;  // the caller's (u1, u2), each in [0, 1)
    std::vector<float> lobe_uniforms;            // with eta and uniforms: the caller's u3 in [0, 1)
};

// The view from polar angle theta and azimuth phi in degrees:
// (sin t cos p, sin t sin p, cos t); theta above 90 is below the horizon.
// Throws InvalidArgument ("theta", "phi") unless theta is in 0 .. 180 and
// phi in -360 .. 360.
Vec3 view_from_angles(double theta_degrees, double phi_degrees);

// Throws InvalidArgument unless the parameters are usable: alpha in
// min_alpha .. max_alpha, view and normal finite and of non-zero length,
// isotropic alpha where the method's traits say so (method_traits), eta 0 or
// finite, > 0 and != 1 (0 for a method without a dielectric sampler), a user
// sampler with Method::user.  The messages name the parameter, the value and
// what is allowed; they are the only checks of a request in ggxcl (the CLI,
// Python and the C API report them).  Views and normals are normalized by the
// caller's choice: normalized() returns a copy with unit vectors.
void validate(const SampleParams& params);
SampleParams normalized(const SampleParams& params);

// v scaled to unit length (computed in double, rounded to float); every
// view and normal the library receives goes through it.
Vec3 unit_vector(const Vec3& v);

// Largest count one range may hold (indices must not wrap around 2^64).
void validate(const SampleRange& range);

// A uniform in [0, 1) given as a double, as a float for PerSampleInputs:
// rounded to the nearest float, and one below 1 that rounds up to 1 becomes
// the largest float below 1 (1 - 2^-24), so that it stays in [0, 1).
float uniform_to_float(double u);

// Each non-empty per-sample vector must hold `count` entries of valid values
// (uniforms finite and in [0, 1): the error names the first bad index);
// lobe_uniforms go with uniforms exactly when params.eta is set.
void validate(const PerSampleInputs& inputs, const SampleParams& params, std::uint64_t count);

// What a request needs, which selects the program variant (see build options):
// whether some view may lie below the horizon (i.n < 1e-6 with the normal of
// uses_normal, iz < 0 in tangent space), and whether every alpha is isotropic.
bool view_above_horizon(const Vec3& view, const Vec3& normal, bool against_normal);
bool all_views_above_horizon(const PerSampleInputs& inputs, const SampleParams& params);
bool all_isotropic(const PerSampleInputs& inputs, const SampleParams& params);

} // namespace ggxcl
