// converge_plan.cpp - checking `ggx converge`'s options, and its lights.
#include "converge_plan.hpp"

#include <cmath>
#include <sstream>

#include "library_errors.hpp"

namespace ggxapp {

namespace {

constexpr double degrees = 3.14159265358979323846 / 180.0;

// A power of two 2^k from "2^k" or a count, for k in [low, high].
int power_of_two(const std::string& flag, const std::string& text, int low, int high)
{
    std::uint64_t n = parse_count(flag, text);
    int k = 0;
    while ((std::uint64_t(1) << k) < n && k < 63)
        ++k;
    if ((std::uint64_t(1) << k) != n || k < low || k > high)
        throw UsageError(flag, text, "a power of two from 2^" + std::to_string(low) + " to 2^" + std::to_string(high));
    return k;
}

} // namespace

std::string integrand_name(Integrand integrand)
{
    switch (integrand) {
    case Integrand::albedo: return "albedo";
    case Integrand::lobe: return "lobe";
    case Integrand::disk: return "disk";
    }
    return "unknown";
}

Integrand integrand_named(const std::string& name)
{
    for (Integrand i : all_integrands)
        if (integrand_name(i) == name)
            return i;
    throw UsageError("--integrands", name, "albedo, lobe or disk");
}

ggxref::Light light_of(Integrand integrand, double theta_degrees)
{
    ggxref::Light light;
    const double t = theta_degrees * degrees;
    if (integrand == Integrand::lobe) {
        light.kind = ggxref::Light::Kind::lobe;
        light.l = {-std::sin(t), 0.0, std::cos(t)};  // the mirror direction of (sin t, 0, cos t)
        light.exponent = 16.0;
    } else if (integrand == Integrand::disk) {
        const double c = t - 7.0 * degrees;  // turned towards the view
        light.kind = ggxref::Light::Kind::disk;
        light.l = {-std::sin(c), 0.0, std::cos(c)};
        light.radius = 10.0 * degrees;
    }
    return light;
}

ggxcl::SampleParams converge_params(const SamplerChoice& method, ggxcl::Sequence sequence, const ConvergeConfig& config,
                                    ggxcl::Precision precision)
{
    ggxcl::SampleParams p;
    method.apply(p);
    p.alpha_x = p.alpha_y = float(config.alpha);
    p.view = ggxcl::view_from_angles(config.theta, 0.0);
    p.precision = precision;
    p.sequence = sequence;
    return ggxcl::normalized(p);
}

ConvergePlan plan_convergence(const ConvergeCommand& cmd, const ApiChoice& api)
{
    ConvergePlan plan;
    std::vector<ggxcl::Method> methods;
    for (const std::string& name : parse_name_list("--methods", cmd.methods, method_names()))
        methods.push_back(ggxcl::parse_method(name));
    plan.methods = sampler_choices(methods, cmd.user.load(api));
    for (const std::string& name : parse_name_list("--sequences", cmd.sequences, {"philox", "sobol"}))
        plan.sequences.push_back(ggxcl::parse_sequence(name));
    for (const std::string& name : parse_name_list("--integrands", cmd.integrands, {"albedo", "lobe", "disk"}))
        plan.integrands.push_back(integrand_named(name));
    std::vector<double> alphas, thetas;
    for (const std::string& a : split_list(cmd.alphas)) {
        double alpha = parse_alpha("--alphas", a)[0];
        if (a.find(',') != std::string::npos || !(alpha >= 0.01 && alpha <= 2.0))
            throw UsageError("--alphas", cmd.alphas, "a comma-separated list of roughnesses in [0.01, 2]");
        alphas.push_back(alpha);
    }
    for (const std::string& t : split_list(cmd.thetas))
        thetas.push_back(parse_angle("--thetas", t, 0.0, 89.0));
    if (alphas.empty() || thetas.empty())
        throw UsageError(alphas.empty() ? "--alphas" : "--thetas", "", "at least one value");
    for (double alpha : alphas)
        for (double theta : thetas)
            plan.configs.push_back({alpha, theta});
    plan.min_exponent = power_of_two("--min-n", cmd.min_n, 0, 24);
    plan.max_exponent = power_of_two("--max-n", cmd.max_n, plan.min_exponent + 2, 24);
    plan.randomizations = int(parse_whole("--randomizations", cmd.randomizations, 4, 4096));
    plan.seed = parse_whole("--seed", cmd.seed, 0, ggxcl::max_seed - std::uint64_t(plan.randomizations) + 1);
    plan.precision = parse_precision_option("--precision", cmd.precision);
    plan.speed_count = cmd.no_speed ? 0 : std::uint32_t(1) << power_of_two("--speed-n", cmd.speed_n, 10, 26);
    return plan;
}

} // namespace ggxapp
