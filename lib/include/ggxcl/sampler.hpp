// sampler.hpp - the ggxcl runtime: draws GGX samples on an OpenCL device
// into host vectors (in bounded chunks) or into the caller's own buffers
// on the caller's queue, and evaluates the pdf of given directions.
//
//   ggxcl::Sampler sampler;                       // GGXCL_DEVICE or the first device
//   ggxcl::SampleParams p{ggxcl::Method::caps, 0.3f, 0.3f, ggxcl::view_from_angles(60, 0)};
//   ggxcl::SampleSet s = sampler.generate(p, {/*seed*/ 1, /*first*/ 0, /*count*/ 1 << 20},
//                                         {ggxcl::Field::m, ggxcl::Field::pdf_m});
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ggxcl/backend.hpp"
#include "ggxcl/device.hpp"
#include "ggxcl/fields.hpp"
#include "ggxcl/opencl.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/results.hpp"

namespace ggxcl {

class ProgramCache;  // the runtime's programs and kernels per context (internal)
class KernelLease;
namespace detail {
class ValidatedParams;  // SampleParams validated once by a public entry point (internal)
struct ProgramVariant;  // the program a launch runs (internal)
}


// Per-sample parameters in the caller's buffers, planar with the stride of
// the call: view and normal 3 planes (unit vectors), alpha 2 planes
// (alpha_x, alpha_y), uniforms 2 planes (u1, u2 in [0, 1); a dielectric's
// 3, with u3), used instead of the sequence of SampleParams; a sample whose uniforms are not in [0, 1)
// is the fallback m = o = n, pdfs and weight 0).  A default-constructed
// buffer means "uniform" (for uniforms: from the sequence).  Each buffer's
// planes start at its offset, in floats (plane c of view at view_offset +
// c * stride): the kernels take the offsets, so any offset costs what 0 does.
// The two flags are promises about the buffers' contents that select a
// cheaper program; leave them false when unsure.  (uniforms comes last so
// that {view, alpha, normal, flags...} initializers keep their meaning.)
struct DeviceInputs {
    cl::Buffer view, alpha, normal;
    bool views_above_horizon = false;  // every view has i.n >= 0 (iz >= 0 in tangent space)
    bool isotropic = false;            // every alpha pair has alpha_x == alpha_y
    cl::Buffer uniforms;
    std::uint64_t view_offset = 0, alpha_offset = 0, normal_offset = 0, uniforms_offset = 0;
};

// One array in a caller's buffer: the buffer and the offset, in floats, where
// the array starts (the kernels take it: no sub-buffer, no copy).  A
// cl::Buffer converts to one at offset 0.
struct DeviceArray {
    cl::Buffer buffer;
    std::uint64_t offset = 0;
    DeviceArray() = default;
    DeviceArray(cl::Buffer whole, std::uint64_t at = 0) : buffer(std::move(whole)), offset(at) {}
};

// Output buffers of the caller, planar with the stride of the call: m and o
// hold 3 planes, u 2 (a dielectric's 3), the others one, each from its
// offset in floats (plane c of m at m_offset + c * stride; the kernels take
// the offsets).  Only the fields whose buffer is set are computed and
// written; nothing else in a buffer is touched.
struct DeviceOutputs {
    cl::Buffer m, o, pdf_m, pdf_o, weight, u;
    std::uint64_t m_offset = 0, o_offset = 0, pdf_m_offset = 0, pdf_o_offset = 0, weight_offset = 0, u_offset = 0;
    cl::Buffer& of(Field field);  // the buffer of `field`
    const cl::Buffer& of(Field field) const;
    std::uint64_t& offset_of(Field field);  // its offset
    std::uint64_t offset_of(Field field) const;
};

// Threads: every member of a Sampler may be called from several threads at
// once, with the bits one thread gets; the calls without a queue argument
// share the sampler's own queue, so for parallel launches give each thread
// its own queue and call enqueue*().  docs/LIBRARY.md "Threads" has the contract.
//
// Errors: InvalidArgument for bad arguments, ClError for OpenCL failures,
// DeviceLost (a ClError) when the device stops working mid-call; a call
// that throws has delivered only whole chunks, in order, to a ChunkSink.
class Sampler : public Backend {
public:
    // A sampler with its own context and in-order queue on the device that
    // `selector` names (see select_device: index or name part; empty means
    // GGXCL_DEVICE, else the first device).
    explicit Sampler(const std::string& selector = "");
    explicit Sampler(const DeviceInfo& device);
    // A sampler on the caller's context; the caller's queues on it are used by enqueue().
    Sampler(const cl::Context& context, const cl::Device& device);

    const cl::Context& context() const { return context_; }
    const cl::Device& device() const { return device_; }
    cl::CommandQueue& queue() { return queue_; }
    Api api() const override { return Api::opencl; }
    std::optional<ShaderLanguage> shader_language() const override { return std::nullopt; }
    std::string device_name() const override;

    // Samples per device pass in generate()/pdf(); memory stays bounded by
    // it and the result does not depend on it.  Default 2^20.
    // When the device runs out of memory (CL_MEM_OBJECT_ALLOCATION_FAILURE,
    // CL_OUT_OF_RESOURCES, CL_OUT_OF_HOST_MEMORY) these calls halve the chunk
    // and go on from the first sample not yet delivered, down to 1024
    // samples; memory_retries() counts the halvings.  Chunks are also kept
    // within the device's largest allocation.
    void set_chunk_size(std::uint64_t samples) override;
    std::uint64_t chunk_size() const override { return chunk_size_; }
    std::uint64_t memory_retries() const { return memory_retries_; }

    // Work-items per work-group of every launch: 0 (the default) picks 256,
    // or the device's maximum if smaller; else 1 .. the device's maximum.
    // Results do not depend on it (sample k is work-item k).
    void set_work_group_size(std::size_t items);
    std::size_t work_group_size() const override;

    // Draws the samples of `range` into host vectors.
    SampleSet generate(const SampleParams& params, const SampleRange& range, FieldSet fields,
                       const PerSampleInputs& per_sample = {}) override;

    // Draws the samples of `range` chunk by chunk (chunk_size() at most) and
    // hands each chunk to `sink` with the offset of its first sample within
    // the range; memory stays bounded whatever the count.
    void generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                         const ChunkSink& sink, const PerSampleInputs& per_sample = {}) override;

    // The same without a copy where the device shares host memory (CPU
    // devices: CL_DEVICE_HOST_UNIFIED_MEMORY): each chunk is the device
    // buffers themselves, mapped for reading; elsewhere it is read into
    // host memory first.  Either way the next chunk is drawn while `sink`
    // runs.  Same values as generate_chunks.
    void generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                              const ChunkViewSink& sink, const PerSampleInputs& per_sample = {}) override;

    // The pdf of each direction o (per steradian) for the sampler of params.method (with
    // params.eta: its dielectric sampler's, both lobes over the whole sphere).
    std::vector<float> pdf(const SampleParams& params, const std::vector<Vec3>& directions,
                           const PerSampleInputs& per_sample = {}) override;
    // The BSDF value f(i, o) |cos theta_o| of each direction o, Fresnel 1 (kernels/ggx_bsdf.h), or
    // with params.eta the rough dielectric's in params.transport (ggx_eval_dielectric), for
    // the view, roughness and normal of params (the same for every method): with pdf(), the pair
    // multiple importance sampling needs; for a sampled o, eval / pdf_o is its weight.
    std::vector<float> eval(const SampleParams& params, const std::vector<Vec3>& directions,
                            const PerSampleInputs& per_sample = {}) override;

    // Enqueues the samples of `range` (count < 2^32) into the caller's
    // buffers on the caller's queue (of this sampler's context).  `stride`
    // is the plane stride in floats of every buffer (0: count).
    cl::Event enqueue(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                      const DeviceOutputs& outputs, std::uint32_t stride = 0,
                      const DeviceInputs& inputs = {}, const std::vector<cl::Event>* wait = nullptr);

    // Builds the program variant that generate() and enqueue() use for
    // `params` with `fields` written (and per-sample inputs of the kinds and
    // promises `inputs` has; their contents are not read) and runs its
    // kernels once on a few samples into scratch buffers, so that a driver
    // that compiles at first launch (PoCL) is done too: the first frame then
    // pays no build.  Variants are shared by every Sampler on this context;
    // repeated calls cost one tiny launch.
    void warm_up(const SampleParams& params, FieldSet fields, const DeviceInputs& inputs = {});

    // Enqueues pdf evaluation of `count` directions (planar, 3 planes) into `pdf_out`.
    cl::Event enqueue_pdf(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                          const DeviceArray& directions, const DeviceArray& pdf_out, std::uint32_t stride = 0,
                          const DeviceInputs& inputs = {}, const std::vector<cl::Event>* wait = nullptr);
    // The same for the BRDF values of eval() into `values`.
    cl::Event enqueue_eval(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                           const DeviceArray& directions, const DeviceArray& values, std::uint32_t stride = 0,
                           const DeviceInputs& inputs = {}, const std::vector<cl::Event>* wait = nullptr);

    // Bins the directions (Field::o or Field::m) of `range` on the device;
    // only the counts come back, so the count of samples is unbounded.
    // bins_phi is 1 .. 65536; bins_z * bins_phi fits the device's local
    // memory (InvalidArgument otherwise).
    Histogram histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                        Field direction = Field::o) override;

    // The fused white-furnace estimator: draws the samples of `range` and
    // sums their weights on the device; nothing per sample is stored.
    FurnaceSums furnace(const SampleParams& params, const SampleRange& range) override;

    // Enqueues it for one range (count <= 2^31): `sums` receives
    // 2 * furnace_items(count) floats, the partial weight sums of the
    // work-items, then their partial sums of squared weights; for a
    // dielectric 3 * furnace_items(count), then those of reflected samples.  The kernel
    // applies the fallbacks of docs/STABILITY.md and so runs slower than
    // furnace(), which draws without them and redraws a launch with them only
    // when one of its sums is not finite.
    cl::Event enqueue_furnace(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                              const DeviceArray& sums, const DeviceInputs& inputs = {},
                              const std::vector<cl::Event>* wait = nullptr);
    std::size_t furnace_items(std::uint64_t count) const;

    // The stability map's cases (Backend::stress): ggx_stress.cl built for the request.
    std::vector<float> stress(const StressRequest& request, const std::vector<float>& in,
                              std::uint32_t count) override;

    // Number of distinct program variants built so far.
    std::size_t programs_built() const;
    // How many of them came from the on-disk binary cache (GGXCL_PROGRAM_CACHE, docs/LIBRARY.md).
    std::size_t programs_from_disk() const;

private:
    // The launches behind the public calls, each of `variant` (detail::variant_of: the program that
    // the request, its guards and its job select) with arguments the public call has validated:
    // they check nothing, so that a call split into chunks or launches validates once.  Their CL
    // errors are the caller's to translate.
    cl::Event launch_samples(cl::CommandQueue& queue, const detail::ProgramVariant& variant,
                             const detail::ValidatedParams& params, const SampleRange& range,
                             const DeviceOutputs& outputs, std::uint32_t stride, const DeviceInputs& inputs,
                             const std::vector<cl::Event>* wait);
    cl::Event launch_directions(cl::CommandQueue& queue, const detail::ProgramVariant& variant,
                                const detail::ValidatedParams& params, std::uint32_t count,
                                const DeviceArray& directions, const DeviceArray& out, std::uint32_t stride,
                                const DeviceInputs& inputs, const std::vector<cl::Event>* wait);
    cl::Event launch_furnace(cl::CommandQueue& queue, const detail::ProgramVariant& variant,
                             const detail::ValidatedParams& params, const SampleRange& range, const DeviceArray& sums,
                             const DeviceInputs& inputs, const std::vector<cl::Event>* wait);
    // pdf() and eval(): the directions through the pdf kernels, chunk by chunk; `variant` is the
    // request's (eval: the BSDF value instead), its per-sample inputs set per chunk.
    std::vector<float> directions_on_host(const detail::ProgramVariant& variant, const detail::ValidatedParams& params,
                                          const std::vector<Vec3>& directions, const PerSampleInputs& per_sample);
    void add_furnace_launch(const detail::ValidatedParams& params, const SampleRange& range, const cl::Buffer& sums,
                            std::vector<float>& host, FurnaceSums& total);
    KernelLease kernel(const std::string& file, const std::string& name, const std::string& options);
    struct HistogramRun;
    // Each chunk as a view (mapped where the device shares host memory), and the host copy it
    // points into where it is not mapped.
    using ChunkDelivery = std::function<void(const SampleView& view, const SampleSet* copy, std::uint64_t offset)>;
    void run_chunks(const detail::ValidatedParams& params, const SampleRange& range, FieldSet fields,
                    const PerSampleInputs& per_sample, const ChunkDelivery& deliver);

    cl::Context context_;
    cl::Device device_;
    cl::CommandQueue queue_;
    std::shared_ptr<ProgramCache> programs_;
    // Settings and the counter are atomic: any thread may set or read them while others draw.
    std::atomic<std::uint64_t> chunk_size_{1u << 20};
    std::atomic<std::size_t> work_group_size_{0};  // 0: automatic
    // What the launches need to know of the device, read once.
    std::size_t device_max_group_ = 1;   // CL_DEVICE_MAX_WORK_GROUP_SIZE
    std::uint64_t max_alloc_ = 0;        // CL_DEVICE_MAX_MEM_ALLOC_SIZE
    std::size_t local_mem_ = 0;          // CL_DEVICE_LOCAL_MEM_SIZE
    std::uint32_t compute_units_ = 1;    // CL_DEVICE_MAX_COMPUTE_UNITS
    bool cpu_ = false;                   // CL_DEVICE_TYPE includes CL_DEVICE_TYPE_CPU
    bool host_unified_ = false;          // CL_DEVICE_HOST_UNIFIED_MEMORY
    std::atomic<std::uint64_t> memory_retries_{0};
};

} // namespace ggxcl
