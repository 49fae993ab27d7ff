// bench_accuracy.hpp - the numerical and statistical accuracy columns of
// `ggx bench`.
//  - Numerical: device samples against the double-precision reference on the
//    same uniforms (alpha 0.05, 0.3, 1 x view 0, 45, 80 degrees): the 99th
//    percentile and maximum of the angle error of m and o, and of the relative
//    error of pdf_m and pdf_o (ndf's pdf_o only where |o.m| >= 1e-2, as in the tests).
//  - Statistical: the per-sample variance of the white-furnace (albedo)
//    estimator, averaged over the cells of a size x size table of views
//    (cos theta = (k + 1/2)/size) and roughnesses (alpha = (k + 1/2)/size):
//    the table a renderer precomputes for energy compensation; and the
//    table's RMSE measured against its exact albedos at a sample count.
//  Both take the device's uniforms from the u field, so any sequence works.
//  - A user sampler's pdf self-consistency: the samples' pdf_o against the
//    pdf its own function recomputes from (i, o).
//  - A rough dielectric's fused furnace: its reflectance and transmittance
//    against the reference's quadrature (ggxref::dielectric_albedo), the
//    errors in standard errors from the spread of independent streams.
#pragma once

#include <cstdint>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_reference.hpp"

namespace ggxapp {

struct NumericalError {
    double angle_p99 = 0, angle_max = 0;  // radians, m and o
    double pdf_p99 = 0, pdf_max = 0;      // relative, pdf_m and pdf_o
    std::uint64_t non_finite = 0;
};

// `who`'s sampler (its method and user sampler) against the reference of `method` on the same
// uniforms: for a built-in method, who.method itself; for a user sampler, the map it reproduces.
NumericalError numerical_error(ggxcl::Backend& sampler, const ggxcl::SampleParams& who, ggxcl::Method method,
                               ggxcl::Precision precision, ggxcl::Sequence sequence = ggxcl::Sequence::philox);

// The fraction of samples with a density whose pdf recomputed from (i, o) by who's own pdf
// function differs from pdf_o by more than 1e-3 (relative), over the accuracy configurations.
double pdf_disagreement(ggxcl::Backend& sampler, const ggxcl::SampleParams& who);

// What the device and the native baseline are both measured on: the 9
// configurations (normalized parameters), samples 0 .. 2^13 - 1 of this seed.
inline constexpr std::uint64_t accuracy_seed = 777, accuracy_samples = 1u << 13;
std::vector<ggxcl::SampleParams> accuracy_configs(ggxcl::Method method, ggxcl::Precision precision);
std::vector<ggxcl::SampleParams> accuracy_configs(const ggxcl::SampleParams& who, ggxcl::Precision precision);

// Angle between two directions (atan2 form, accurate near 0) and relative error.
double angle_between(const ggxref::Vec3& a, const ggxref::Vec3& b);
double relative_error(double value, double reference);

// The 99th percentile and maximum of `errors` (left as they are when empty).
void percentiles(std::vector<double>& errors, double& p99, double& max);

struct SceneVariance {
    double variance = 0;     // per-sample variance of the weight, mean over cells
    double mean_albedo = 0;  // mean over cells of the albedo estimate
};

// Of `who`'s sampler (its method and user sampler), as below.
SceneVariance albedo_scene_variance(ggxcl::Backend& sampler, const ggxcl::SampleParams& who,
                                    ggxcl::Precision precision, int size, std::uint64_t samples_per_cell);

// The exact albedo of every cell of the size x size table (reference
// quadrature), cell a * size + v.
std::vector<double> albedo_table(int size);

// The table's RMSE against `exact` from `samples_per_cell` samples per cell
// of `sequence`, over `streams` independent streams (seeds; for Sobol points
// independent scrambles) of each cell: measured, for any sequence.
double albedo_table_rmse(ggxcl::Backend& sampler, const ggxcl::SampleParams& who, ggxcl::Precision precision,
                         ggxcl::Sequence sequence, int size, std::uint64_t samples_per_cell, int streams,
                         const std::vector<double>& exact);

struct DielectricAccuracy {
    bool measured = false;
    std::uint64_t samples = 0;                      // over all streams
    double reflectance = 0, transmittance = 0;      // the furnace's means over the streams
    double reflectance_se = 0, transmittance_se = 0;  // their standard errors, from the streams' spread
    double exact_reflectance = 0, exact_transmittance = 0;
    double reflectance_z() const { return (reflectance - exact_reflectance) / reflectance_se; }
    double transmittance_z() const { return (transmittance - exact_transmittance) / transmittance_se; }
};

inline constexpr int dielectric_streams = 32;
inline constexpr std::uint64_t dielectric_stream_samples = 1u << 17;

// The exact reflectance and transmittance of params (eta and transport set).
ggxref::DielectricAlbedo dielectric_exact(const ggxcl::SampleParams& params);

// Backend::furnace over dielectric_streams streams of dielectric_stream_samples each.
DielectricAccuracy dielectric_accuracy(ggxcl::Backend& sampler, const ggxcl::SampleParams& params,
                                       const ggxref::DielectricAlbedo& exact);

} // namespace ggxapp
