// program_variant.hpp - a program the runtime builds, as plain values: the
// kernel file and every specialization its -D options select.  The runtime
// makes one from each request (variant_of) and writes its options from it
// (variant_defines); tests/support/program_variants.hpp enumerates them without a device,
// for the offline GPU compilers (tests/gpu_compilers).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ggxcl/fields.hpp"
#include "ggxcl/method.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/user_sampler.hpp"

namespace ggxcl::detail {

// The 0|1 specializations of the bulk kernels (kernels/ggx_bulk.cl), each
// with its macro: one line per option writes it and enumerates it.
#define GGX_PROGRAM_FLAGS(X)                          \
    X(per_sample_view, "GGX_PER_SAMPLE_VIEW")         \
    X(per_sample_alpha, "GGX_PER_SAMPLE_ALPHA")       \
    X(per_sample_normal, "GGX_PER_SAMPLE_NORMAL")     \
    X(per_sample_uniforms, "GGX_PER_SAMPLE_UNIFORMS") \
    X(isotropic, "GGX_ISOTROPIC")                     \
    X(below_horizon, "GGX_BELOW_HORIZON")             \
    X(world_space, "GGX_WORLD_SPACE")                 \
    X(guards, "GGX_GUARDS")                           \
    X(normal_is_z, "GGX_NORMAL_IS_Z")                 \
    X(dielectric, "GGX_DIELECTRIC")                   \
    X(importance, "GGX_IMPORTANCE")                   \
    X(eval, "GGX_EVAL")

// The programs the runtime builds: one kernel file each.
// (The stability map's kernels/ggx_stress.cl belongs to `ggx stress`, which writes its options.)
enum class ProgramKind { bulk, furnace, histogram };
inline constexpr ProgramKind all_program_kinds[] = {ProgramKind::bulk, ProgramKind::furnace, ProgramKind::histogram};
const char* program_file(ProgramKind kind);  // "ggx_bulk.cl", ...
const char* program_kind_name(ProgramKind kind);  // "bulk", ...

struct HistogramBins {
    int bins_z = 0, bins_phi = 0;
    bool of_m = false;  // bins the microfacet normal m instead of o
};

struct ProgramVariant {
    ProgramKind kind = ProgramKind::bulk;
    Method method = Method::caps;
    Precision precision = Precision::precise;
    Sequence sequence = Sequence::philox;
    unsigned write_mask = 0;  // bits 1 << GGX_FIELD_*
#define GGX_PROGRAM_FLAG_MEMBER(field, macro) bool field = false;
    GGX_PROGRAM_FLAGS(GGX_PROGRAM_FLAG_MEMBER)
#undef GGX_PROGRAM_FLAG_MEMBER
    HistogramBins bins;  // histogram programs only
    std::shared_ptr<const UserSampler> user;  // method user: the sampler's file
};

// The variant a request builds with no per-sample inputs: its method, precision, sequence and
// guards, the fields written, and what the request needs (isotropic, views below the horizon,
// world space, n = z).  The bulk program's pdf kernels evaluate the BSDF instead with eval = true
// (set by the caller).  OpenCL's with the caller's buffers: kernel_launch.hpp.
ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask);

// What a request's per-sample inputs are, wherever they live (host arrays here, the caller's
// cl::Buffers in opencl/kernel_launch): which are given, and what holds over all samples.
struct PerSampleKinds {
    bool view = false, alpha = false, normal = false, uniforms = false;
    bool isotropic = true, above_horizon = true;  // every alpha pair, every view
};
// The variant of a request with per-sample inputs of these kinds.
ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                          const PerSampleKinds& kinds);

// The same for per-sample inputs in host memory (the Vulkan back end): what the caller's arrays hold
// decides the per-sample flags and the promises.
ProgramVariant variant_of_host_inputs(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                                      const PerSampleInputs& inputs);

// The macros a variant defines, NAME and value, the same on every device and in every language
// (variant_defines writes them as -D options; shaders get them from shaderc).
std::vector<std::pair<std::string, long>> variant_define_list(const ProgramVariant& variant);

// The -D options of a variant, the same on every device (the precision mode's options and the
// device's quirks are added by the caller: precision_options, device_quirk_options).
std::string variant_defines(const ProgramVariant& variant);

// The variant with what its kind fixes: a furnace writes the weight only; a histogram writes no
// field, has no per-sample inputs and keeps the guards; only a histogram has bins; only the bulk
// program's pdf kernels evaluate the BRDF instead (eval).
ProgramVariant with_kind_fixed(ProgramVariant variant);

// Whether variant_of can give this variant for some valid request (caps-iso and world space are
// isotropic; a per-sample normal is never promised to be z; importance transport with a dielectric
// only, and a dielectric only for the methods that have its sampler; what with_kind_fixed fixes).
bool variant_is_reachable(const ProgramVariant& variant);

// What tells two variants apart: the kind, the precision and the -D options.
std::string variant_key(const ProgramVariant& variant);

} // namespace ggxcl::detail
