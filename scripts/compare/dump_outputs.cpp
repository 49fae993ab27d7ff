// dump_outputs.cpp - prints, as exact text, what ggxcl's public API returns
// for a fixed set of requests, so that two builds of the library (before and
// after a refactor) can be compared with cmp or diff.  scripts/compare-outputs.sh
// compiles it once against each build and runs both.
//
// For every method and a few configurations of each (isotropic and
// anisotropic alpha, a view below the horizon, caps-iso about a tilted
// normal, a dielectric eta 1.5), in precise mode, on OpenCL (the default
// device) and on Vulkan (the default device; GLSL shaders, and HLSL for the
// first configuration of each method):
// samples with every field (philox and sobol), pdf and eval of a fixed set of
// directions, histograms of o (and m), furnace sums (philox, and sobol).  Floats are printed with
// %a (exact); a call that throws prints its message instead.
//
// Only API that exists in every version compared may be used here (it must
// compile against 21598c6): Sampler, VulkanSampler and the types of
// params.hpp, fields.hpp, method.hpp.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ggxcl/fields.hpp"
#include "ggxcl/method.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/sampler.hpp"
#include "ggxcl/vulkan.hpp"

namespace {

constexpr std::uint64_t kSeed = 7, kSamples = 1024, kBinned = 1 << 16, kFurnace = 1 << 16;
constexpr int kBinsZ = 16, kBinsPhi = 32, kPerLine = 16;

struct Config {
    std::string name;
    ggxcl::SampleParams params;
};

ggxcl::SampleParams request(ggxcl::Method method, float ax, float ay, double theta, double phi)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.view = ggxcl::view_from_angles(theta, phi);
    p.precision = ggxcl::Precision::precise;
    return p;
}

// The configurations of every method that its traits allow.
std::vector<Config> configs()
{
    std::vector<Config> list;
    for (ggxcl::Method method : ggxcl::all_methods) {
        const ggxcl::MethodTraits& traits = ggxcl::method_traits(method);
        const std::string name(traits.name);
        list.push_back({name + " iso a0.3 theta60", request(method, 0.3f, 0.3f, 60, 0)});
        if (!traits.isotropic_only)
            list.push_back({name + " aniso a0.1,0.5 theta45 phi30", request(method, 0.1f, 0.5f, 45, 30)});
        if (traits.views_below)
            list.push_back({name + " below a0.3 theta120 phi10", request(method, 0.3f, 0.3f, 120, 10)});
        if (traits.space == ggxcl::Space::world) {
            Config tilted{name + " tilted normal 0,0.6,0.8 theta50 phi200", request(method, 0.2f, 0.2f, 50, 200)};
            tilted.params.normal = {0.0f, 0.6f, 0.8f};
            list.push_back(tilted);
        }
        if (traits.dielectric) {
            Config glass{name + " eta1.5 a0.3 theta60", request(method, 0.3f, 0.3f, 60, 0)};
            glass.params.eta = 1.5f;
            list.push_back(glass);
        }
    }
    return list;
}

// Fixed directions over the whole sphere (a spiral of equal area), both lobes of a dielectric.
std::vector<ggxcl::Vec3> directions()
{
    std::vector<ggxcl::Vec3> dirs;
    const int count = 48;
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
        dirs.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
    }
    return dirs;
}

void print_floats(const std::string& tag, const std::vector<float>& values)
{
    if (values.empty())
        std::printf("%s (none)\n", tag.c_str());
    for (std::size_t j = 0; j < values.size(); j += kPerLine) {
        std::printf("%s [%zu]", tag.c_str(), j);
        for (std::size_t k = j; k < values.size() && k < j + kPerLine; ++k)
            std::printf(" %a", double(values[k]));
        std::printf("\n");
    }
}

// Runs one call; an exception becomes a line of its own, so both outputs stay comparable.
void attempt(const std::string& tag, const std::function<void()>& call)
{
    try {
        call();
    } catch (const std::exception& e) {
        std::printf("%s throws: %s\n", tag.c_str(), e.what());
    }
}

// Samples of both sequences, and furnace sums (of sobol's points only with `every`: each
// request is a program build on a cold cache).
template <class S>
void dump_samples(S& sampler, const std::string& tag, ggxcl::SampleParams params, bool every)
{
    for (ggxcl::Sequence sequence : ggxcl::all_sequences) {
        params.sequence = sequence;
        const std::string at = tag + " " + std::string(ggxcl::sequence_name(sequence));
        attempt(at + " generate", [&] {
            const ggxcl::SampleSet set = sampler.generate(params, {kSeed, 0, kSamples}, ggxcl::FieldSet::all());
            std::printf("%s generate count %llu\n", at.c_str(), static_cast<unsigned long long>(set.count));
            for (ggxcl::Field field : ggxcl::all_fields)
                print_floats(at + " " + std::string(ggxcl::field_name(field)), set.column_source(field));
        });
        if (sequence == ggxcl::Sequence::sobol && !every)
            continue;
        attempt(at + " furnace", [&] {
            const ggxcl::FurnaceSums s = sampler.furnace(params, {kSeed, 0, kFurnace});
            std::printf("%s furnace count %llu sum %a squares %a reflected %a\n", at.c_str(),
                        static_cast<unsigned long long>(s.count), s.sum, s.sum_of_squares, s.reflected_sum);
        });
    }
}

// Histograms of o (and of m with `every`).
template <class S>
void dump_histograms(S& sampler, const std::string& tag, const ggxcl::SampleParams& params, bool every)
{
    for (ggxcl::Field direction : {ggxcl::Field::o, ggxcl::Field::m}) {
        if (direction == ggxcl::Field::m && !every)
            continue;
        const std::string at = tag + " histogram " + std::string(ggxcl::field_name(direction));
        attempt(at, [&] {
            const ggxcl::Histogram h = sampler.histogram(params, {kSeed, 0, kBinned}, kBinsZ, kBinsPhi, direction);
            std::printf("%s bins %dx%d non_finite %llu invalid %llu counts", at.c_str(), h.bins_z, h.bins_phi,
                        static_cast<unsigned long long>(h.non_finite), static_cast<unsigned long long>(h.invalid));
            for (std::uint64_t c : h.counts)
                std::printf(" %llu", static_cast<unsigned long long>(c));
            std::printf("\n");
        });
    }
}

// Everything of one back end (ggxcl::Sampler or ggxcl::VulkanSampler).  The sobol furnace and
// the histogram of m for the first configuration of each method alone, and with `first_only`
// nothing of the others: on a cold cache each request costs a program or shader build (~1.5 s).
template <class S>
void dump_api(S& sampler, const std::string& api, bool first_only = false)
{
    const std::vector<ggxcl::Vec3> dirs = directions();
    const std::vector<Config> list = configs();
    for (std::size_t c = 0; c < list.size(); ++c) {
        const Config& config = list[c];
        const bool first = c == 0 || list[c - 1].params.method != config.params.method;
        if (first_only && !first)
            continue;
        const std::string tag = api + " | " + config.name + " |";
        dump_samples(sampler, tag, config.params, first);
        attempt(tag + " pdf", [&] { print_floats(tag + " pdf", sampler.pdf(config.params, dirs)); });
        attempt(tag + " eval", [&] { print_floats(tag + " eval", sampler.eval(config.params, dirs)); });
        dump_histograms(sampler, tag, config.params, first);
    }
}

void dump_vulkan(ggxcl::ShaderLanguage language)
{
    const std::string api = std::string("vulkan-") + ggxcl::shader_language_name(language);
    if (!ggxcl::vulkan_built()) {
        std::printf("%s: absent (this build of ggxcl has no Vulkan back end)\n", api.c_str());
        return;
    }
    std::unique_ptr<ggxcl::VulkanSampler> sampler;
    try {
        sampler = std::make_unique<ggxcl::VulkanSampler>("", language);
    } catch (const std::exception& e) {
        std::printf("%s: absent (no device: %s)\n", api.c_str(), e.what());
        return;
    }
    std::printf("%s: device %s\n", api.c_str(), sampler->device_name().c_str());
    dump_api(*sampler, api, language == ggxcl::ShaderLanguage::hlsl);
}

} // namespace

int main()
{
    static char buffer[1 << 16];
    std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
    std::printf("dump_outputs: seed %llu, %llu samples, %llu binned into %dx%d, %llu in the furnace\n",
                static_cast<unsigned long long>(kSeed), static_cast<unsigned long long>(kSamples),
                static_cast<unsigned long long>(kBinned), kBinsZ, kBinsPhi,
                static_cast<unsigned long long>(kFurnace));
    try {
        ggxcl::Sampler sampler;
        std::printf("opencl: device %s\n", sampler.device_name().c_str());
        dump_api(sampler, "opencl");
    } catch (const std::exception& e) {
        std::printf("opencl: failed: %s\n", e.what());
        std::fflush(stdout);
        return 1;
    }
    dump_vulkan(ggxcl::ShaderLanguage::glsl);
    dump_vulkan(ggxcl::ShaderLanguage::hlsl);
    std::fflush(stdout);
    return 0;
}
