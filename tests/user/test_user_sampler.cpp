// test_user_sampler.cpp - a sampler in one file through the library: a
// copy of caps gives caps' bits in every front end (samples in both
// sequences and precisions, pdf, furnace, histogram, enqueue); a sampler
// of m alone is completed as heitz's samples are; an edited file (or an
// edited file it includes) builds anew; a file that does not compile, or
// lacks a function or its claim, is refused naming the file (and line);
// Method::user and user_sampler come together, on conductors in tangent space.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <ggxcl/ggxcl.hpp>

#include "bit_compare.hpp"
#include "completed_samples.hpp"
#include "discarded_counts.hpp"
#include "device_fixture.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

using ggxtest::same_bits;

using ggxtest::user_sampler_file;

ggxcl::SampleParams user_params(const std::string& file, float ax = 0.2f, float ay = 0.5f)
{
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::user;
    p.user_sampler = ggxcl::UserSampler::load(user_sampler_file(file));
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.view = ggxcl::view_from_angles(70.0, 20.0);
    return p;
}

ggxcl::SampleParams as_method(ggxcl::SampleParams p, ggxcl::Method method)
{
    p.method = method;
    p.user_sampler = nullptr;
    return p;
}

// A scratch folder of this process.
fs::path scratch(const std::string& tag)
{
    fs::path dir = fs::temp_directory_path() / ("ggx-user-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write(const fs::path& path, const std::string& text)
{
    std::ofstream(path) << text;
}

// A sampler file of caps whose pdf is scaled by the macro SCALE of "scale.h" beside it.
const char* scaled_caps = R"(#include "ggx_samplers.h"
#include "scale.h"
#define GGX_USER_DISTRIBUTION GGX_USER_VNDF
GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_caps(i, ax, ay, u1, u2);
}
GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return SCALE * ggx_pdf_caps(i, o, ax, ay);
}
)";

} // namespace

TEST_CASE("a user sampler that is caps gives caps' bits in every front end")
{
    ggxcl::Sampler& sampler = ggxtest::sampler();
    const ggxcl::SampleParams user = user_params("caps_copy.h");
    const ggxcl::SampleParams caps = as_method(user, ggxcl::Method::caps);
    CHECK(user.user_sampler->name() == "caps_copy");
    CHECK(user.user_sampler->distribution() == ggxcl::Distribution::vndf);
    CHECK_FALSE(user.user_sampler->samples_m());
    CHECK(ggxcl::sampler_name(user) == "caps_copy");
    const ggxcl::SampleRange range{7, 1000, 4099};
    for (ggxcl::Sequence sequence : ggxcl::all_sequences)
        for (ggxcl::Precision precision : ggxcl::all_precisions) {
            CAPTURE(ggxcl::sequence_name(sequence));
            CAPTURE(ggxcl::precision_name(precision));
            ggxcl::SampleParams u = user, c = caps;
            u.sequence = c.sequence = sequence;
            u.precision = c.precision = precision;
            CHECK(same_bits(sampler.generate(u, range, ggxcl::FieldSet::all()),
                            sampler.generate(c, range, ggxcl::FieldSet::all())));
        }
    const ggxcl::SampleSet drawn = sampler.generate(caps, range, {ggxcl::Field::o});
    std::vector<ggxcl::Vec3> directions;
    for (std::size_t j = 0; j < drawn.count; ++j)
        directions.push_back(drawn.o_at(j));
    CHECK(same_bits(sampler.pdf(user, directions), sampler.pdf(caps, directions)));
    const ggxcl::FurnaceSums a = sampler.furnace(user, range), b = sampler.furnace(caps, range);
    CHECK(a.sum == b.sum);
    CHECK(a.sum_of_squares == b.sum_of_squares);
    const ggxcl::Histogram ha = sampler.histogram(user, range, 16, 32), hb = sampler.histogram(caps, range, 16, 32);
    ggxtest::check_counts_with_discards(ha, hb);
}

TEST_CASE("a user sampler of m alone is completed: heitz's m, o and weight, its own pdf")
{
    ggxcl::Sampler& sampler = ggxtest::sampler();
    const ggxcl::SampleParams user = user_params("heitz_normal_only.h");
    CHECK(user.user_sampler->samples_m());
    const ggxcl::SampleRange range{3, 0, 5000};
    const ggxcl::SampleSet mine = sampler.generate(user, range, ggxcl::FieldSet::all());
    const ggxcl::SampleSet heitz = sampler.generate(as_method(user, ggxcl::Method::heitz), range, ggxcl::FieldSet::all());
    ggxtest::check_completed_like_heitz(mine, heitz);
}

TEST_CASE("an edited user sampler, or an edited file it includes, is built anew")
{
    ggxcl::Sampler& sampler = ggxtest::sampler();
    const fs::path dir = scratch("edit");
    write(dir / "scaled.h", scaled_caps);
    write(dir / "scale.h", "#define SCALE 1.0f\n");
    auto pdf_of = [&](const std::shared_ptr<const ggxcl::UserSampler>& loaded) {
        ggxcl::SampleParams p = user_params("caps_copy.h");
        p.user_sampler = loaded;
        return sampler.pdf(p, {ggxcl::Vec3{0.1f, 0.2f, 0.9f}})[0];
    };
    const auto first = ggxcl::UserSampler::load((dir / "scaled.h").string());
    const float one = pdf_of(first);
    CHECK(one > 0.0f);
    write(dir / "scale.h", "#define SCALE 3.0f\n");
    const auto second = ggxcl::UserSampler::load((dir / "scaled.h").string());
    CHECK(second->key() != first->key());
    CHECK(pdf_of(second) == doctest::Approx(3.0f * one).epsilon(1e-6));
    CHECK(pdf_of(first) == one);  // the first text's program is still the first's
    std::string edited = scaled_caps;
    edited.replace(edited.find("SCALE *"), 7, "0.5f * SCALE *");
    write(dir / "scaled.h", edited);
    const auto third = ggxcl::UserSampler::load((dir / "scaled.h").string());
    CHECK(pdf_of(third) == doctest::Approx(1.5f * one).epsilon(1e-6));
    fs::remove_all(dir);
}

TEST_CASE("a user sampler that does not compile names its file and line")
{
    ggxcl::SampleParams p = user_params("syntax_error.h");
    try {
        ggxtest::sampler().generate(p, {0, 0, 10}, {ggxcl::Field::o});
        FAIL("no BuildError");
    } catch (const ggxcl::BuildError& error) {
        const std::string what = error.what();
        CAPTURE(what);
        CHECK(what.rfind("the user sampler does not compile: ", 0) == 0);
        CHECK(what.substr(0, what.find('\n')).find("syntax_error.h:9:") != std::string::npos);
        CHECK(what.rfind("the user sampler does not compile: " + user_sampler_file("syntax_error.h") + ":9:", 0) == 0);
    }
}

TEST_CASE("a user sampler file without a function, a claim or a good name is refused, naming it")
{
    const fs::path dir = scratch("refused");
    struct Case {
        std::string text, name, parameter, named;
    };
    const std::string pdf = "GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay) { return 0; }\n";
    const std::string sample = "GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, "
                               "float u2) { return ggx_fallback_sample(i); }\n";
    const std::string claim = "#define GGX_USER_DISTRIBUTION GGX_USER_OWN\n";
    const Case cases[] = {
        {claim + sample, "", "sampler", "ggx_user_pdf"},
        {claim + pdf + "// ggx_user_sample(i, ax, ay, u1, u2) in a comment\n", "", "sampler", "ggx_user_sample"},
        {sample + pdf, "", "sampler", "GGX_USER_DISTRIBUTION"},
        {claim + sample + pdf, "caps", "sampler name", "built-in"},
        {claim + sample + pdf, "a b", "sampler name", "letters"},
        {"#include \"missing_helper.h\"\n" + claim + sample + pdf, "", "sampler", "missing_helper.h"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.text);
        write(dir / "s.h", c.text);
        try {
            ggxcl::UserSampler::load((dir / "s.h").string(), c.name);
            FAIL("not refused");
        } catch (const ggxcl::InvalidArgument& error) {
            CHECK(error.parameter() == c.parameter);
            CHECK(std::string(error.what()).find(c.named) != std::string::npos);
        }
    }
    CHECK_THROWS_AS(ggxcl::UserSampler::load((dir / "none.h").string()), ggxcl::InvalidArgument);
    fs::remove_all(dir);
}

TEST_CASE("Method::user and user_sampler come together, on a conductor in tangent space")
{
    ggxcl::SampleParams p = user_params("caps_copy.h");
    auto refused_naming = [](ggxcl::SampleParams params, const std::string& parameter) {
        try {
            ggxcl::validate(params);
            return false;
        } catch (const ggxcl::InvalidArgument& error) {
            return error.parameter() == parameter;
        }
    };
    ggxcl::validate(p);
    ggxcl::SampleParams no_file = p;
    no_file.user_sampler = nullptr;
    CHECK(refused_naming(no_file, "user_sampler"));
    CHECK_NOTHROW(ggxcl::validate(as_method(p, ggxcl::Method::caps)));
    ggxcl::SampleParams both = p;
    both.method = ggxcl::Method::caps;
    CHECK(refused_naming(both, "method"));
    ggxcl::SampleParams glass = p;
    glass.eta = 1.5f;
    CHECK(refused_naming(glass, "eta"));
    ggxcl::SampleParams world = p;
    world.world_space = true;
    world.alpha_y = world.alpha_x;
    CHECK(refused_naming(world, "world_space"));
}

TEST_CASE("a view opposite the normal is refused for a user sampler claiming visible normals or its own density, "
          "kept for one claiming the NDF")
{
    ggxcl::Sampler& sampler = ggxtest::sampler();
    for (const char* file : {"caps_copy.h", "harness/bounded_own.h", "harness/ndf_copy.h"}) {
        CAPTURE(file);
        ggxcl::SampleParams p = user_params(file);
        p.view = ggxcl::view_from_angles(180.0, 0.0);
        if (p.user_sampler->distribution() == ggxcl::Distribution::ndf) {
            CHECK(sampler.generate(p, {1, 0, 100}, {ggxcl::Field::o}).count == 100);
            continue;
        }
        const std::string message =
            ggxtest::message_of<ggxcl::InvalidArgument>([&] { sampler.generate(p, {1, 0, 100}, {ggxcl::Field::o}); });
        CHECK(message.find("invalid view") != std::string::npos);
        CHECK(message.find(p.user_sampler->name()) != std::string::npos);
    }
}
