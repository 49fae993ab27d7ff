// sample_options.cpp - shared sampling options and their validation.
#include "sample_options.hpp"

#include <limits>

#include "cli_values.hpp"
#include "library_errors.hpp"

namespace ggxapp {

void SampleOptions::add_view_options(CLI::App& cmd)
{
    cmd.add_option("--alpha", alpha, std::string("GGX roughness AX or AX,AY, each ") + ggxcl::alpha_range);
    cmd.add_option("--theta", theta, "view polar angle in degrees, 0..180 (above 90: below the horizon)");
    cmd.add_option("--phi", phi, "view azimuth in degrees, -360..360");
    cmd.add_option("--seed", seed, std::string("seed of the stream of uniforms, ") + ggxcl::seed_range);
    cmd.add_option("--sequence", sequence, "where the uniforms come from: philox (independent) or sobol "
                                           "(Owen-scrambled Sobol points, keyed by --seed)");
    cmd.add_option("--precision", precision, "precise (sincos within 0.86 ulp; division and sqrt correctly rounded "
                                             "where the device reports CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) or "
                                             "relaxed (-cl-fast-relaxed-math)");
    cmd.add_option("--device", device,
                   "device index or name part (see `ggx devices`; vulkan:NAME where the command takes --api); default "
                   "GGXCL_DEVICE, else the first");
    cmd.add_option("--eta", eta, "a rough dielectric: index below the surface over index above (e.g. 1.5), each "
                                 "sample reflected or refracted with the exact Fresnel; 0: a conductor, Fresnel 1 "
                                 "(the methods with a dielectric sampler: `ggx methods`)");
    cmd.add_option("--transport", transport, "with --eta: radiance (transmission divided by eta^2, for path "
                                             "tracing) or importance");
}

void SampleOptions::add_method_options(CLI::App& cmd)
{
    CLI::Option* by_method =
        cmd.add_option("--method", method, "sampler: " + ggxcl::method_list() + "; this or --sampler is required");
    CLI::Option* by_file =
        cmd.add_option("--sampler", sampler, "a sampler of your own in FILE.h (OpenCL C), FILE.glsl or FILE.hlsl "
                                             "(Vulkan) instead of --method (docs/USER-SAMPLERS.md)");
    by_method->excludes(by_file);
    cmd.add_option("--sampler-name", sampler_name, "the --sampler's name in reports (default: the file's stem)")
        ->needs(by_file);
    cmd.add_option("--normal", normal, "for a method in world space (caps-iso): the surface normal X,Y,Z "
                                       "(default 0,0,1)");
    cmd.callback([by_method, by_file] {
        if (by_method->count() == 0 && by_file->count() == 0)
            throw CLI::RequiredError("--method or --sampler");
    });
}

std::shared_ptr<const ggxcl::UserSampler> load_user_sampler(const std::string& file, const std::string& name,
                                                            const ApiChoice& api)
{
    try {
        return ggxcl::UserSampler::load(file, name, api.sampler_language(file));
    } catch (const ggxcl::InvalidArgument& error) {
        const bool bad_name = error.parameter() == "sampler name";
        throw UsageError(bad_name ? "--sampler-name" : "--sampler", bad_name ? name : file, error.allowed());
    }
}

std::string SamplerChoice::name() const
{
    return user ? user->name() : std::string(ggxcl::method_name(method));
}

void SamplerChoice::apply(ggxcl::SampleParams& params) const
{
    params.method = method;
    params.user_sampler = user;
}

std::vector<SamplerChoice> sampler_choices(const std::vector<ggxcl::Method>& methods,
                                           const std::vector<std::shared_ptr<const ggxcl::UserSampler>>& users)
{
    std::vector<SamplerChoice> choices;
    for (ggxcl::Method method : methods)
        choices.push_back({method, nullptr});
    for (const auto& user : users)
        choices.push_back({ggxcl::Method::user, user});
    return choices;
}

void UserSamplerOptions::add_to(CLI::App& cmd)
{
    cmd.add_option("--sampler", files, "a sampler of your own in FILE.h (OpenCL C), FILE.glsl or FILE.hlsl "
                                       "(Vulkan), beside the methods (repeatable; docs/USER-SAMPLERS.md)");
    cmd.add_option("--sampler-name", names, "the name of the k-th --sampler in reports (repeatable; default: the "
                                            "file's stem)");
}

std::vector<std::shared_ptr<const ggxcl::UserSampler>> UserSamplerOptions::load(const ApiChoice& api) const
{
    return load(std::vector<ApiChoice>{api});
}

std::vector<std::shared_ptr<const ggxcl::UserSampler>> UserSamplerOptions::load(const std::vector<ApiChoice>& apis) const
{
    if (names.size() > files.size())
        throw UsageError("--sampler-name", names.back(), "at most one name per --sampler");
    std::vector<std::shared_ptr<const ggxcl::UserSampler>> loaded;
    for (std::size_t k = 0; k < files.size(); ++k) {
        loaded.push_back(load_user_sampler(files[k], k < names.size() ? names[k] : "", choice_for_file(files[k], apis)));
        for (std::size_t j = 0; j < k; ++j)
            if (loaded[j]->name() == loaded[k]->name())
                throw UsageError("--sampler-name", loaded[k]->name(),
                                 "a name per sampler: two samplers are named " + loaded[k]->name());
    }
    return loaded;
}

ggxcl::SampleParams SampleOptions::parsed_params(const ApiChoice& api) const
{
    if (sampler.empty())
        return params_for(parsed_method());
    return params_for(ggxcl::Method::user, load_user_sampler(sampler, sampler_name, api));
}

std::vector<std::string> method_names()
{
    std::vector<std::string> names;
    for (ggxcl::Method m : ggxcl::all_methods)
        names.emplace_back(ggxcl::method_name(m));
    return names;
}

ggxcl::Method SampleOptions::parsed_method() const
{
    return parse_method_option("--method", method);
}

std::uint64_t SampleOptions::parsed_seed() const { return parse_whole("--seed", seed, 0, ggxcl::max_seed); }

ggxcl::Sequence SampleOptions::parsed_sequence() const
{
    return parsed_option("--sequence", sequence, "one of philox, sobol", ggxcl::parse_sequence);
}

float SampleOptions::parsed_eta() const { return parse_eta("--eta", eta); }

ggxcl::Transport SampleOptions::parsed_transport() const
{
    return parse_transport_option("--transport", transport);
}

ggxcl::SampleRange SampleOptions::parsed_range(const std::string& first, const std::string& count) const
{
    ggxcl::SampleRange range{parsed_seed(), parse_uint64("--first", first), parse_count("-n", count)};
    const std::uint64_t room = std::numeric_limits<std::uint64_t>::max() - range.first;
    if (range.count > room)  // found by fuzz/fuzz_cli: refused by the library only after a device was opened
        throw UsageError("-n", count, "at most 2^64 - 1 - --first = " + std::to_string(room) + " samples");
    return range;
}

double SampleOptions::parsed_theta() const { return parse_number("--theta", theta); }
double SampleOptions::parsed_phi() const { return parse_number("--phi", phi); }

SampleOptions SampleOptions::for_method(ggxcl::Method method) const
{
    SampleOptions options = *this;
    if (ggxcl::method_traits(method).isotropic_only)
        options.alpha = alpha.substr(0, alpha.find(','));
    return options;
}

OptionsOfParameters SampleOptions::option_of_parameter() const
{
    return {{"alpha", {"--alpha", alpha}}, {"theta", {"--theta", theta}}, {"phi", {"--phi", phi}},
            {"eta", {"--eta", eta}},       {"normal", {"--normal", normal}}};
}

ggxcl::SampleParams SampleOptions::params_for(ggxcl::Method m, std::shared_ptr<const ggxcl::UserSampler> user) const
{
    ggxcl::SampleParams p;
    p.method = m;
    p.user_sampler = std::move(user);
    const std::array<float, 2> a = parse_alpha("--alpha", alpha);
    p.alpha_x = a[0];
    p.alpha_y = a[1];
    p.precision = parse_precision_option("--precision", precision);
    p.sequence = parsed_sequence();
    p.eta = parsed_eta();
    p.transport = parsed_transport();
    if (!normal.empty()) {
        if (ggxcl::method_traits(m).space != ggxcl::Space::world)
            throw UsageError("--normal", normal,
                             "only with a method that works in world space (caps-iso); the others work in tangent space");
        std::array<float, 3> n = parse_vec3("--normal", normal);
        p.normal = {n[0], n[1], n[2]};
    }
    const double theta_degrees = parsed_theta(), phi_degrees = parsed_phi();
    return in_option_terms(option_of_parameter(), [&] {
        p.view = ggxcl::view_from_angles(theta_degrees, phi_degrees);
        return ggxcl::normalized(p);
    });
}

} // namespace ggxapp
