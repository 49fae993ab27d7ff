// planar_inputs.hpp - planes and host arrays, for any back end: the
// caller's per-sample inputs of a chunk as the planes the bulk kernels and
// shaders read (component c of entry j at c * capacity + j), and a chunk's
// output planes (a view, where the device wrote them) copied into host memory.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ggxcl/params.hpp"
#include "ggxcl/results.hpp"

namespace ggxcl::detail {

// Entries [start, start+n) of `values` as planes of stride `capacity`, unit length.
std::vector<float> planar_units(const std::vector<Vec3>& values, std::uint64_t start, std::uint64_t n,
                                std::uint64_t capacity);

// Pairs (alphas, uniforms) [start, start+n) as two planes of stride `capacity`;
// the unused rest holds 0.5, valid for both.
std::vector<float> planar_pairs(const std::vector<std::array<float, 2>>& values, std::uint64_t start,
                                std::uint64_t n, std::uint64_t capacity);

// The caller's uniforms [start, start+n): u1 and u2 as planar_pairs, then for a dielectric the
// plane of u3 (0.5 in the unused rest).
std::vector<float> planar_uniforms(const PerSampleInputs& in, std::uint64_t start, std::uint64_t n,
                                   std::uint64_t capacity);

// The chunk as a SampleSet of its own: its planes packed at stride count.
SampleSet copy_of(const SampleView& chunk, FieldSet fields, bool dielectric);

// The chunk into `all` (planes all.count apart) at `offset`; a field's whole array is allocated
// when its first chunk arrives.
void copy_into(SampleSet& all, const SampleView& chunk, std::uint64_t offset, FieldSet fields, bool dielectric);

} // namespace ggxcl::detail
