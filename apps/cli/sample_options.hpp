// sample_options.hpp - the sampling options `ggx sample` and `ggx demo`
// share (method, roughness, view, normal, seed, device) and their
// conversion into ggxcl parameters, with usage errors naming the flag.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <ggxcl/ggxcl.hpp>

#include "api_options.hpp"
#include "library_errors.hpp"

namespace ggxapp {

// The method names in ggxcl::all_methods order, for lists of methods.
std::vector<std::string> method_names();

// The user sampler in `file`, named `name` (empty: the file's stem), in the
// language `api` reads it in; throws UsageError naming --sampler or --sampler-name.
std::shared_ptr<const ggxcl::UserSampler> load_user_sampler(const std::string& file, const std::string& name,
                                                            const ApiChoice& api);

// A sampler the comparing commands run: a built-in method, or Method::user with its file.
struct SamplerChoice {
    ggxcl::Method method = ggxcl::Method::caps;
    std::shared_ptr<const ggxcl::UserSampler> user;
    std::string name() const;                       // the method's name, or the user sampler's
    void apply(ggxcl::SampleParams& params) const;  // sets params.method and params.user_sampler
    bool operator==(const SamplerChoice& other) const { return method == other.method && user == other.user; }
};

// The built-in methods of --methods, then the user samplers.
std::vector<SamplerChoice> sampler_choices(const std::vector<ggxcl::Method>& methods,
                                           const std::vector<std::shared_ptr<const ggxcl::UserSampler>>& users);

// The repeatable --sampler FILE and --sampler-name NAME of the commands that compare samplers
// (the k-th name names the k-th file), added to `cmd`.
struct UserSamplerOptions {
    std::vector<std::string> files, names;
    void add_to(CLI::App& cmd);
    // Each file loaded; UsageError for more names than files, a bad file or name, or two
    // samplers of one name.
    std::vector<std::shared_ptr<const ggxcl::UserSampler>> load(const ApiChoice& api) const;
    // The same with several APIs: each file read for the API that runs it (choice_for_file).
    std::vector<std::shared_ptr<const ggxcl::UserSampler>> load(const std::vector<ApiChoice>& apis) const;
};

struct SampleOptions {
    std::string method;  // required (or --sampler) where add_method_options adds it
    std::string alpha = "0.3";
    std::string theta = "60";
    std::string phi = "0";
    std::string normal;  // caps-iso only
    std::string seed = "0";
    std::string device;  // selector, else GGXCL_DEVICE, else the first device
    std::string precision = "precise";
    std::string sequence = "philox";
    std::string eta = "0";  // a rough dielectric's relative index; 0: a conductor
    std::string transport = "radiance";
    std::string sampler, sampler_name;  // a user sampler's file (instead of --method) and its name

    // --alpha, --theta, --phi, --seed, --sequence, --device, --precision, --eta, --transport
    void add_view_options(CLI::App& cmd);
    void add_method_options(CLI::App& cmd); // --method or --sampler (--sampler-name), --normal

    // These options for a command that runs every method: caps-iso, which is
    // isotropic, takes the first value of an AX,AY roughness.
    SampleOptions for_method(ggxcl::Method method) const;

    // The parameters for `method`; throws UsageError naming the bad flag.
    ggxcl::SampleParams params_for(ggxcl::Method method,
                                   std::shared_ptr<const ggxcl::UserSampler> user = nullptr) const;
    // The parameters of --method, or of --sampler (Method::user).
    ggxcl::SampleParams parsed_params(const ApiChoice& api) const;
    ggxcl::Method parsed_method() const;
    std::uint64_t parsed_seed() const;
    ggxcl::Sequence parsed_sequence() const;
    float parsed_eta() const;
    ggxcl::Transport parsed_transport() const;
    // --seed, --first and -n; the range must end before index 2^64.
    ggxcl::SampleRange parsed_range(const std::string& first, const std::string& count) const;
    double parsed_theta() const;  // numbers; params_for checks them (the library's rule)
    double parsed_phi() const;
    // The options that set the library's parameters, for its messages (library_errors.hpp).
    OptionsOfParameters option_of_parameter() const;
};

} // namespace ggxapp
