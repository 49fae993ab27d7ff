// device_fixture.hpp - what the device tests share: one Sampler on the
// default device (PoCL on the CPU unless GGXCL_DEVICE says otherwise), the
// conversion of reference parameters to library parameters, device samples
// as reference vectors, and the configuration grids the tests sweep.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_quadrature.hpp"
#include "reference_bridge.hpp"
#include "ggx_reference.hpp"
#include "ggx_stats.hpp"

namespace ggxtest {

ggxcl::Sampler& sampler();

ggxcl::Method to_library(ggxref::Method method);
ggxcl::SampleParams to_library(ggxref::Method method, const ggxref::Params& params,
                               ggxcl::Precision precision = ggxcl::Precision::precise);

inline constexpr ggxcl::Precision all_precisions[] = {ggxcl::Precision::precise, ggxcl::Precision::relaxed};

// The reference parameters of a view at (theta, phi) degrees, normal +z.
ggxref::Params make_params(double ax, double ay, double theta_degrees, double phi_degrees = 35.0);

// Unit-length double copy of a float direction (as the library normalizes it).
ggxref::Vec3 unit(const ggxcl::Vec3& v);

struct Config {
    ggxref::Params params;
    std::string label;
};

// The float parameters the device sees, as the reference takes them (the bridge's doubles, unit in
// double), so that both work on the same inputs.
Config as_device_sees(const ggxref::Params& p);

// A world normal tilted by `tilt` degrees towards azimuth 120, and the view given in the frame of
// that normal at (theta, phi 35) degrees.
ggxref::Params tilted(double alpha, double theta, double tilt);

// Per-sample grid: alpha 0.01..2, anisotropy up to 1:10, theta 0..85 degrees.
// For caps-iso only the isotropic pairs, with normals away from +z as well.
std::vector<Config> per_sample_grid(ggxref::Method method);

// 20 configurations per method for the chi-square tests.
std::vector<Config> distribution_grid(ggxref::Method method);

// Both alphas above 1, where bounded's k < 0: (1.5, 1.5) and (1.3, 2.0) at 0, 52 and 88 degrees.
std::vector<Config> rough_bounded_grid();

// Device samples of one configuration: o (or m) as a directions set.
ggxcl::SampleSet device_samples(ggxref::Method method, const ggxref::Params& params, std::uint64_t seed,
                                std::uint64_t count, ggxcl::FieldSet fields,
                                ggxcl::Precision precision = ggxcl::Precision::precise,
                                ggxcl::Sequence sequence = ggxcl::Sequence::philox);

// The reference's uniforms of sample `index` of stream `seed` in `sequence`.
std::array<double, 2> reference_uniforms(ggxcl::Sequence sequence, std::uint64_t seed, std::uint64_t index);

// |device - reference| <= rel |reference| + abs, and the device value finite.
bool close_to(double device, double reference, double rel, double abs);

// Runs `kernel` of `kernels` (OpenCL C appended to the device headers, ggx_samplers.h, built with
// the device's options) over `items` work-items: arguments (const float* in, float* out), `in` as
// given, `outputs_per_item` floats of out per work-item, read back.
std::vector<float> run_user_kernel(const std::string& kernels, const std::string& kernel, const std::vector<float>& in,
                                   std::size_t items, std::size_t outputs_per_item);

// Histogram of the o (planar) of a sample set in the reference binning.
std::vector<std::uint64_t> histogram_of(const std::vector<float>& planar, std::uint64_t count, int nz, int nphi);

std::string describe(const ggxref::Params& params);

} // namespace ggxtest
