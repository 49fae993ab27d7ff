// test_sequences.cpp - the uniforms' sequences in the bulk kernels
// (SampleParams::sequence):
//  - with Sobol points every method matches the double-precision reference
//    fed the reference's own Sobol uniforms, sample by sample, with the
//    bounds of test_per_sample but 2e-2 for the worst pdf (below); the u
//    field is bit for bit the reference's uniforms, for philox and sobol;
//  - the Sobol stream is the same whatever the chunk size or the split into
//    ranges (sample k is point k), and the first 2^m samples of a stream
//    are a (0, m, 2)-net in the u the kernels used;
//  - the sequence selects the program: philox and sobol differ, and the
//    default is philox.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "bit_compare.hpp"
#include "sample_compare.hpp"

namespace {

using ggxcl::Field;
using ggxcl::Sequence;

constexpr std::uint64_t samples_per_config = 1024;
constexpr std::uint64_t seed = 977;

// The worst sample's pdf bound is twice test_per_sample's: a Sobol point
// lands near caps' cap rim (alpha (0.2, 2), view 60 degrees, u2 = 0.9985),
// where c + v cancels and i.m = 2.2e-3 carries its absolute rounding into
// pdf_m = 4 (i.m) pdf_o: 1.4e-2 relative on rusticl (no fma), 3e-3 on PoCL.
constexpr ggxtest::ErrorBound sobol_pdf_bound{"relative error of pdf_m and pdf_o", 2e-4, 2e-2};

ggxcl::SampleParams caps_at(double alpha, double theta, Sequence sequence)
{
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::caps;
    p.alpha_x = p.alpha_y = float(alpha);
    p.view = ggxcl::view_from_angles(theta, 20.0);
    p.sequence = sequence;
    return p;
}

// The u field against the reference's uniforms of the sequence, bit for bit.
std::size_t uniforms_differing(const ggxcl::SampleSet& s, Sequence sequence, std::uint64_t stream,
                               std::uint64_t first)
{
    std::size_t differ = 0;
    for (std::size_t j = 0; j < s.count; ++j) {
        std::array<double, 2> u = ggxtest::reference_uniforms(sequence, stream, first + j);
        differ += s.u[j] != float(u[0]) || s.u[s.count + j] != float(u[1]);
    }
    return differ;
}

} // namespace

TEST_CASE("with Sobol points every method matches the reference sample by sample")
{
    for (ggxref::Method method : ggxref::all_methods) {
        CAPTURE(std::string(ggxref::method_name(method)));
        ggxtest::SampleErrors errors;
        std::size_t differing = 0;
        for (const ggxtest::Config& config : ggxtest::per_sample_grid(method)) {
            ggxcl::SampleSet d = ggxtest::device_samples(method, config.params, seed, samples_per_config,
                                                         ggxcl::FieldSet::all(), ggxcl::Precision::precise,
                                                         Sequence::sobol);
            differing += uniforms_differing(d, Sequence::sobol, seed, 0);
            auto reference = [&](std::size_t, double u1, double u2) {
                return ggxref::sample(method, config.params, u1, u2);
            };
            ggxtest::compare_samples(d, seed, reference, method == ggxref::Method::ndf, config.label, errors,
                                     Sequence::sobol);
        }
        CHECK(differing == 0);
        ggxtest::check_sample_errors(std::string(ggxref::method_name(method)) + " sobol", errors,
                                     ggxtest::angle_bound, sobol_pdf_bound);
    }
}

TEST_CASE("the u field holds the sequence's uniforms bit for bit, at any offset")
{
    for (Sequence sequence : ggxcl::all_sequences) {
        CAPTURE(ggxcl::sequence_name(sequence));
        for (std::uint64_t first : {std::uint64_t(0), std::uint64_t(123457), (std::uint64_t(1) << 32) - 700}) {
            CAPTURE(first);
            ggxcl::SampleSet s = ggxtest::sampler().generate(caps_at(0.3, 60, sequence), {41, first, 3000}, {Field::u});
            CHECK(uniforms_differing(s, sequence, 41, first) == 0);
        }
    }
    // Control: the Philox words are not the Sobol words.
    ggxcl::SampleSet philox = ggxtest::sampler().generate(caps_at(0.3, 60, Sequence::philox), {41, 0, 3000}, {Field::u});
    CHECK(uniforms_differing(philox, Sequence::sobol, 41, 0) > 2900);
}

TEST_CASE("a Sobol stream has the same bits whatever the chunks and ranges")
{
    auto& s = ggxtest::sampler();
    const ggxcl::SampleParams p = caps_at(0.2, 45, Sequence::sobol);
    const std::uint64_t n = 10000;
    ggxcl::SampleSet whole = s.generate(p, {5, 0, n}, ggxcl::FieldSet::all());
    const std::uint64_t saved = s.chunk_size();
    s.set_chunk_size(1536);
    ggxcl::SampleSet chunked = s.generate(p, {5, 0, n}, ggxcl::FieldSet::all());
    s.set_chunk_size(saved);
    CHECK(ggxtest::same_bits(whole, chunked));
    CHECK(ggxtest::same_bits(whole.u, chunked.u));
    ggxcl::SampleSet head = s.generate(p, {5, 0, 4097}, {Field::o, Field::u});
    ggxcl::SampleSet tail = s.generate(p, {5, 4097, n - 4097}, {Field::o, Field::u});
    std::size_t differ = 0;
    for (std::uint64_t j = 0; j < n; ++j) {
        const ggxcl::SampleSet& part = j < 4097 ? head : tail;
        std::uint64_t k = j < 4097 ? j : j - 4097;
        differ += part.o_at(k).x != whole.o_at(j).x || part.o_at(k).z != whole.o_at(j).z ||
                  part.u[k] != whole.u[j] || part.u[part.count + k] != whole.u[n + j];
    }
    CHECK(differ == 0);
}

TEST_CASE("the first 2^m samples of a Sobol stream use a (0, m, 2)-net of uniforms")
{
    const int m = 12;
    const std::uint64_t n = std::uint64_t(1) << m;
    for (std::uint64_t stream : {0u, 8u, 4000000000u}) {
        CAPTURE(stream);
        ggxcl::SampleSet s = ggxtest::sampler().generate(caps_at(0.3, 60, Sequence::sobol), {stream, 0, n}, {Field::u});
        bool net = true;
        for (int j = 0; j <= m; ++j) {  // cells of 2^-j by 2^-(m-j)
            std::vector<int> seen(n, 0);
            for (std::uint64_t k = 0; k < n; ++k) {
                auto a = std::uint64_t(std::ldexp(s.u[k], j)), b = std::uint64_t(std::ldexp(s.u[n + k], m - j));
                net &= ++seen[(a << (m - j)) | b] == 1;
            }
        }
        CHECK(net);
    }
    // Control: Philox uniforms are no net.
    ggxcl::SampleSet p = ggxtest::sampler().generate(caps_at(0.3, 60, Sequence::philox), {0, 0, n}, {Field::u});
    std::vector<int> seen(n, 0);
    bool net = true;
    for (std::uint64_t k = 0; k < n; ++k)
        net &= ++seen[(std::uint64_t(std::ldexp(p.u[k], 6)) << 6) | std::uint64_t(std::ldexp(p.u[n + k], 6))] == 1;
    CHECK_FALSE(net);
}

TEST_CASE("the default sequence is philox, and the sequences give different samples")
{
    CHECK(ggxcl::SampleParams{}.sequence == Sequence::philox);
    auto& s = ggxtest::sampler();
    ggxcl::SampleSet philox = s.generate(caps_at(0.3, 30, Sequence::philox), {3, 0, 512}, {Field::m});
    ggxcl::SampleSet sobol = s.generate(caps_at(0.3, 30, Sequence::sobol), {3, 0, 512}, {Field::m});
    ggxcl::SampleParams unset = caps_at(0.3, 30, Sequence::philox);
    CHECK(ggxtest::same_bits(philox.m, s.generate(unset, {3, 0, 512}, {Field::m}).m));
    std::size_t same = 0;
    for (std::size_t j = 0; j < 512; ++j)
        same += philox.m[j] == sobol.m[j];
    CHECK(same < 5);
    CHECK(ggxcl::parse_sequence("sobol") == Sequence::sobol);
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([] { ggxcl::parse_sequence("halton"); }) ==
          "invalid sequence 'halton': allowed is one of philox, sobol");
}
