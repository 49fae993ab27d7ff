// converge_plan.hpp - what `ggx converge` measures: for each method and
// sequence of uniforms, the error of Monte Carlo estimates of integrals the
// reference knows exactly, against the sample count, over a table of
// roughnesses and view angles.  The options as typed, the plan they give
// once checked (planning touches no file and no device), and the
// integrands with the lights they place about each view.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_integrals.hpp"
#include "sample_options.hpp"

namespace ggxapp {

// The integrals int brdf_cos(i, o) L(o) do estimated by the mean of weight * L(o):
//   albedo - L = 1, the white furnace (directional albedo);
//   lobe   - L = max(0, o.l)^16 about the mirror direction of the view: smooth;
//   disk   - L = 1 on a disk of angular radius 10 degrees whose centre is the
//            mirror direction turned 7 degrees towards the view in the plane
//            of incidence: a discontinuous edge across the BRDF's peak.
enum class Integrand { albedo, lobe, disk };
inline constexpr Integrand all_integrands[] = {Integrand::albedo, Integrand::lobe, Integrand::disk};
std::string integrand_name(Integrand integrand);
Integrand integrand_named(const std::string& name);

// The light of `integrand` for a view at theta degrees (phi = 0), tangent space.
ggxref::Light light_of(Integrand integrand, double theta_degrees);

struct ConvergeConfig {
    double alpha = 0.3, theta = 45.0;  // isotropic roughness, view angle in degrees (phi = 0)
};

struct ConvergeCommand {
    std::string methods = "all", sequences = "philox,sobol", integrands = "albedo,lobe,disk";
    std::string alphas = "0.05,0.3,1", thetas = "0,45,80";
    std::string min_n = "2^4", max_n = "2^16", randomizations = "32", seed = "1";
    std::string precision = "precise", device, speed_n = "2^22";
    bool no_speed = false;
    std::string csv, charts, markdown, html;
    UserSamplerOptions user;  // --sampler FILE.h (repeatable), --sampler-name
};

struct ConvergePlan {
    std::vector<SamplerChoice> methods;  // the built-in methods, then the user samplers
    std::vector<ggxcl::Sequence> sequences;
    std::vector<Integrand> integrands;
    std::vector<ConvergeConfig> configs;
    int min_exponent = 4, max_exponent = 16;  // sample counts 2^min .. 2^max
    int randomizations = 32;                   // independent seeds seed .. seed + R - 1
    std::uint64_t seed = 1;
    ggxcl::Precision precision = ggxcl::Precision::precise;
    std::uint32_t speed_count = 1u << 22;      // samples per timed launch; 0: no timing
};

// Throws UsageError naming the first bad option; `api` reads the --sampler files.
ConvergePlan plan_convergence(const ConvergeCommand& cmd, const ApiChoice& api);

// The library's parameters of one configuration (isotropic, view at phi = 0).
ggxcl::SampleParams converge_params(const SamplerChoice& method, ggxcl::Sequence sequence, const ConvergeConfig& config,
                                    ggxcl::Precision precision);

} // namespace ggxapp
