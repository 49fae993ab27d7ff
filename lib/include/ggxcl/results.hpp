// results.hpp - what a sampler returns, on any API: samples on the host
// (SampleSet) or in the back end's memory during a call (SampleView), the
// chunk sinks that receive them, histogram counts and furnace sums.  No
// OpenCL or Vulkan header: backend.hpp, sampler.hpp and vulkan.hpp share it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl {

// Samples on the host.  Fields of several columns are planar: m[c * count + j]
// is component c (x, y, z) of sample j, u[c * count + j] its uniform u1 (c = 0)
// or u2 (c = 1), and a dielectric's u3 (c = 2).  Fields not requested stay empty.
struct SampleSet {
    std::uint64_t count = 0;
    std::vector<float> m, o, pdf_m, pdf_o, weight, u;

    Vec3 m_at(std::size_t j) const { return {m[j], m[count + j], m[2 * count + j]}; }
    Vec3 o_at(std::size_t j) const { return {o[j], o[count + j], o[2 * count + j]}; }
    const std::vector<float>& column_source(Field field) const;
    std::vector<float>& column_source(Field field);
};

// A chunk of samples in memory the back end owns, valid only during the call
// that receives it: planar like SampleSet but with planes `stride` floats
// apart (m[c * stride + j] is component c of sample j); fields not
// requested are null.
struct SampleView {
    std::uint64_t count = 0, stride = 0;
    const float *m = nullptr, *o = nullptr, *pdf_m = nullptr, *pdf_o = nullptr, *weight = nullptr, *u = nullptr;
    const float* column_source(Field field) const;
    const float*& column_source(Field field);
};
SampleView view_of(const SampleSet& set);  // its fields, stride = count

// Receivers of generate_chunks and generate_chunk_views: each chunk with the
// offset of its first sample within the range.
using ChunkSink = std::function<void(const SampleSet& chunk, std::uint64_t offset)>;
using ChunkViewSink = std::function<void(const SampleView& chunk, std::uint64_t offset)>;

// Counts of directions in bins of equal solid angle over (phi, cos theta):
// z = cos(theta) in [-1, 1] split into bins_z, phi in [0, 2 pi) into
// bins_phi; counts[z_bin * bins_phi + phi_bin].  Of a dielectric's o the
// whole sphere holds both lobes.
struct Histogram {
    int bins_z = 0, bins_phi = 0;
    std::vector<std::uint64_t> counts;
    std::uint64_t non_finite = 0;  // samples whose direction was NaN or Inf
    // Dielectrics (SampleParams::eta): samples without density (pdf_o = 0, a
    // reflection that left the view's side or a transmission that did not
    // cross), counted here instead of in a bin.  A user sampler
    // (Method::user): its discarded samples (o below the horizon with weight
    // 0, whatever their pdf), o or m binned.
    std::uint64_t invalid = 0;
    std::uint64_t total() const;
};

// Sums of the white-furnace estimator weights (Fresnel 1, or a
// dielectric's) of a range of samples: their mean estimates the directional
// albedo of the surface.  For a dielectric (SampleParams::eta) the weights
// of reflected samples (o on the view's side) are also summed apart: the
// mean splits into reflectance + transmittance.
struct FurnaceSums {
    std::uint64_t count = 0;
    double sum = 0.0, sum_of_squares = 0.0;
    double reflected_sum = 0.0;  // dielectrics: the reflected samples' weights (else 0)
    double mean() const;           // the albedo estimate
    double variance() const;       // per-sample variance of the weight
    double reflectance() const;    // reflected_sum / count
    double transmittance() const;  // (sum - reflected_sum) / count
};

} // namespace ggxcl
