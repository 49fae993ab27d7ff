// test_backend_contract.cpp - what every Backend promises about its calls
// (backend.hpp), on the back end of GGX_TEST_API (backend_fixture.hpp; CTest
// runs it on OpenCL and on Vulkan):
//   - a range drawn in chunks, or as two shards, gives the bits of one call,
//     every field;
//   - bad requests are refused with the value and what is allowed: a chunk
//     size of 0, a negative alpha_x, stress inputs of the wrong size.
// Control: a range shifted by one sample gives other bits, so the
// comparisons can fail.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "backend_fixture.hpp"
#include "device_fixture.hpp"

namespace {

using ggxcl::Field;

const ggxcl::FieldSet every_field{Field::m, Field::o, Field::pdf_m, Field::pdf_o, Field::weight, Field::u};

ggxcl::SampleParams request()
{
    ggxcl::SampleParams p = ggxtest::to_library(ggxref::Method::caps, ggxtest::make_params(0.2, 0.7, 70.0),
                                                ggxcl::Precision::precise);
    return p;
}

} // namespace

TEST_CASE("chunks and shards give the bits of one call")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    const ggxcl::SampleParams p = request();
    const std::uint64_t chunk = backend->chunk_size();
    const ggxcl::SampleSet whole = backend->generate(p, {3, 1000, 10000}, every_field);
    backend->set_chunk_size(1536);
    const ggxcl::SampleSet chunked = backend->generate(p, {3, 1000, 10000}, every_field);
    backend->set_chunk_size(chunk);
    const ggxcl::SampleSet head = backend->generate(p, {3, 1000, 4000}, every_field);
    const ggxcl::SampleSet tail = backend->generate(p, {3, 5000, 6000}, every_field);
    CHECK(chunked.m == whole.m);
    CHECK(chunked.o == whole.o);
    CHECK(chunked.pdf_m == whole.pdf_m);
    CHECK(chunked.pdf_o == whole.pdf_o);
    CHECK(chunked.weight == whole.weight);
    CHECK(chunked.u == whole.u);
    CHECK(std::equal(head.pdf_o.begin(), head.pdf_o.end(), whole.pdf_o.begin()));
    CHECK(std::equal(tail.pdf_o.begin(), tail.pdf_o.end(), whole.pdf_o.begin() + 4000));
    for (int c = 0; c < 3; ++c) {  // plane c of the shards against the whole's
        CHECK(std::equal(head.o.begin() + c * 4000, head.o.begin() + (c + 1) * 4000, whole.o.begin() + c * 10000));
        CHECK(std::equal(tail.o.begin() + c * 6000, tail.o.begin() + (c + 1) * 6000, whole.o.begin() + c * 10000 + 4000));
    }
    const ggxcl::SampleSet shifted = backend->generate(p, {3, 1001, 10000}, every_field);  // the control
    CHECK(shifted.o != whole.o);
}

TEST_CASE("bad requests are refused with the value and what is allowed")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    CHECK_THROWS_AS(backend->set_chunk_size(0), ggxcl::InvalidArgument);
    ggxcl::SampleParams bad = request();
    bad.alpha_x = -1.0f;
    CHECK_THROWS_WITH_AS(backend->generate(bad, {1, 0, 10}, {Field::o}), doctest::Contains("alpha_x"),
                         ggxcl::InvalidArgument);
    CHECK_THROWS_WITH_AS(backend->stress({ggxcl::Method::caps}, std::vector<float>(25), 3),
                         doctest::Contains("30 (10 planes of 3 cases)"), ggxcl::InvalidArgument);
}
