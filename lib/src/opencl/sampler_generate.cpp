// sampler_generate.cpp - Sampler::generate, generate_chunks and pdf: the
// host-memory front end that runs the bulk kernels chunk by chunk through
// device buffers of bounded size, halving the chunk when the device runs
// out of memory.  Each call validates its request once at its start; the
// chunks launch through launch_samples and launch_directions.  Chunks are
// mapped where the device shares host memory, read into host vectors
// elsewhere.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "chunk_inputs.hpp"
#include "cl_call.hpp"
#include "device_contract.hpp"
#include "kernel_launch.hpp"
#include "planar_inputs.hpp"
#include "queue_waits.hpp"
#include "device_faults.hpp"
#include "validated_params.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"

namespace ggxcl {

namespace {

using detail::translate_cl_errors;

constexpr std::uint64_t smallest_chunk = 1024;  // samples; out of memory below it is an error

std::size_t bytes(std::uint64_t floats)
{
    return static_cast<std::size_t>(floats * sizeof(float));
}

// Reads the first n entries of each of `planes` planes (stride capacity) into `host`.
void read_planes(cl::CommandQueue& queue, const cl::Buffer& buffer, int planes, std::uint64_t n,
                 std::uint64_t capacity, std::vector<float>& host)
{
    host.resize(planes * n);
    for (int c = 0; c < planes; ++c)
        queue.enqueueReadBuffer(buffer, CL_FALSE, bytes(c * capacity), bytes(n), host.data() + c * n);
}

// Waits for everything on the queue when it goes out of scope, so that no
// copy into a host vector is in flight when the vector is freed (a sink or
// a launch that throws leaves commands behind).  It waits on a marker, not
// clFinish (queue_waits.hpp: rusticl's clFinish after a flush returned with
// the last fetch still queued, which then wrote into freed memory).
struct QueueDrain {
    cl::CommandQueue& queue;
    ~QueueDrain()
    {
        try {
            detail::drain(queue);
        } catch (...) {  // a lost device: nothing more will run
        }
    }
};

// One of the two chunk slots of run_chunks: device outputs, and either
// their host copies or (mapped) pointers into them, with the marker that
// says the copies or maps are complete.
class ChunkSlot {
public:
    ChunkSlot(const cl::Context& context, FieldSet fields, std::uint64_t capacity, bool map, bool dielectric)
        : fields_(fields), capacity_(capacity), map_(map), dielectric_(dielectric)
    {
        for (Field f : all_fields)
            if (fields.has(f))
                out_.of(f) = detail::device_buffer(context, map ? CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR : CL_MEM_WRITE_ONLY,
                                                  bytes(columns(f) * capacity));
    }

    DeviceOutputs& outputs() { return out_; }
    const SampleSet& host_copy() const { return host_; }
    std::uint64_t start = 0;

    // Enqueues the copy (or map) of the first n samples after the kernel.
    void fetch(cl::CommandQueue& queue, std::uint64_t n)
    {
        count_ = n;
        host_.count = n;
        for (Field f : all_fields) {
            if (!fields_.has(f))
                continue;
            if (map_)
                mapped_[int(f)] = static_cast<float*>(
                    queue.enqueueMapBuffer(out_.of(f), CL_FALSE, CL_MAP_READ, 0, bytes(columns(f) * capacity_)));
            else
                read_planes(queue, out_.of(f), columns(f), n, capacity_, host_.column_source(f));
        }
        queue.enqueueMarkerWithWaitList(nullptr, &ready_);
        queue.flush();
    }

    // Waits for the fetch and describes the chunk.
    SampleView view()
    {
        ready_.wait();
        SampleView v;
        v.count = count_;
        v.stride = map_ ? capacity_ : count_;
        for (Field f : all_fields)
            if (fields_.has(f))
                v.column_source(f) = map_ ? mapped_[int(f)] : host_.column_source(f).data();
        return v;
    }

    // After the sink: the maps are given back before the buffers are written again.
    void release(cl::CommandQueue& queue)
    {
        if (!map_)
            return;
        for (Field f : all_fields)
            if (fields_.has(f))
                queue.enqueueUnmapMemObject(out_.of(f), mapped_[int(f)]);
    }

private:
    int columns(Field f) const { return field_columns(f, dielectric_); }

    FieldSet fields_;
    std::uint64_t capacity_, count_ = 0;
    bool map_, dielectric_;
    DeviceOutputs out_;
    SampleSet host_;
    float* mapped_[all_fields.size()] = {};
    cl::Event ready_;
};

// The chunk capacity: the requested one, within the count, and small enough
// that a buffer of `planes` planes fits the device's largest allocation.
std::uint64_t fitted_capacity(std::uint64_t max_alloc, std::uint64_t requested, std::uint64_t count, int planes)
{
    std::uint64_t largest = max_alloc / (planes * sizeof(float));
    return std::max<std::uint64_t>(1, std::min({requested, count, largest}));
}

} // namespace

void Sampler::run_chunks(const detail::ValidatedParams& params, const SampleRange& range, FieldSet fields,
                         const PerSampleInputs& per_sample, const ChunkDelivery& deliver)
{
    const bool map = host_unified_;
    translate_cl_errors([&] {
        std::uint64_t start = 0, chunk = fitted_capacity(max_alloc_, chunk_size_, range.count, 3);
        detail::retry_with_smaller_chunks(chunk, smallest_chunk, memory_retries_, [&](std::uint64_t capacity) {
            // Two slots: the device draws and fetches chunk k + 1 while the sink takes chunk k.
            const bool dielectric = (*params).eta != 0.0f;
            ChunkSlot slots[2] = {ChunkSlot(context_, fields, capacity, map, dielectric),
                                  ChunkSlot(context_, fields, capacity, map, dielectric)};
            detail::ChunkInputs inputs(context_, per_sample, *params, capacity);
            const detail::ProgramVariant variant = detail::variant_of(
                detail::ProgramKind::bulk, *params, detail::write_mask(fields), inputs.buffers);
            QueueDrain drain{queue_};      // before the slots go, whatever ends the pass
            std::uint64_t next = start;    // the first sample not yet enqueued
            ChunkSlot* pending = nullptr;  // enqueued, not yet delivered
            auto deliver_pending = [&] {
                SampleView view = pending->view();
                deliver(view, map ? nullptr : &pending->host_copy(), pending->start);
                pending->release(queue_);
                start = pending->start + view.count;
            };
            for (int k = 0; start < range.count; ++k) {  // start: the first sample not delivered
                ChunkSlot* slot = nullptr;
                if (next < range.count) {
                    slot = &slots[k % 2];  // its previous chunk was delivered and released in the last round
                    std::uint64_t n = std::min(capacity, range.count - next);
                    try {
                        // Blocking, on the in-order queue: after the previous chunk's kernel has read them.
                        inputs.upload(queue_, per_sample, next, n, capacity);
                        launch_samples(queue_, variant, params, {range.seed, range.first + next, n},
                                       slot->outputs(), std::uint32_t(capacity), inputs.buffers, nullptr);
                    } catch (...) {
                        // The chunk drawn before this one may be whole: it reaches the sink first.
                        if (pending)
                            try {
                                deliver_pending();
                            } catch (...) {
                            }
                        throw;
                    }
                    slot->start = next;
                    slot->fetch(queue_, n);
                    next += n;
                }
                if (pending)
                    deliver_pending();
                pending = slot;
            }
        });
        return 0;
    });
}

namespace detail {

ValidatedParams validated_request(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                  const PerSampleInputs& per_sample)
{
    ValidatedParams valid = validated(params);
    validate(range);
    validate(per_sample, params, range.count);
    if (fields.empty())
        throw InvalidArgument("fields", "none", "at least one of " + field_list());
    return valid;
}

} // namespace detail

void Sampler::generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                   const ChunkViewSink& sink, const PerSampleInputs& per_sample)
{
    run_chunks(detail::validated_request(params, range, fields, per_sample), range, fields, per_sample,
               [&](const SampleView& view, const SampleSet*, std::uint64_t offset) { sink(view, offset); });
}

void Sampler::generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                              const ChunkSink& sink, const PerSampleInputs& per_sample)
{
    const bool dielectric = params.eta != 0.0f;
    run_chunks(detail::validated_request(params, range, fields, per_sample), range, fields, per_sample,
               [&](const SampleView& view, const SampleSet* copy, std::uint64_t offset) {
                   sink(copy ? *copy : detail::copy_of(view, fields, dielectric), offset);
               });
}

SampleSet Sampler::generate(const SampleParams& params, const SampleRange& range, FieldSet fields,
                            const PerSampleInputs& per_sample)
{
    const detail::ValidatedParams valid = detail::validated_request(params, range, fields, per_sample);
    SampleSet all;
    all.count = range.count;
    const bool dielectric = (*valid).eta != 0.0f;
    auto copy_chunk = [&](const SampleView& chunk, const SampleSet*, std::uint64_t offset) {
        detail::copy_into(all, chunk, offset, fields, dielectric);
    };
    run_chunks(valid, range, fields, per_sample, copy_chunk);
    return all;
}

std::vector<float> Sampler::pdf(const SampleParams& params, const std::vector<Vec3>& directions,
                                const PerSampleInputs& per_sample)
{
    const detail::ValidatedParams valid = detail::validated(params);
    return directions_on_host(detail::variant_of(detail::ProgramKind::bulk, *valid, 0), valid, directions, per_sample);
}

std::vector<float> Sampler::eval(const SampleParams& params, const std::vector<Vec3>& directions,
                                 const PerSampleInputs& per_sample)
{
    const detail::ValidatedParams valid = detail::validated(params);
    detail::ProgramVariant variant = detail::variant_of(detail::ProgramKind::bulk, *valid, 0);
    variant.eval = true;
    return directions_on_host(variant, valid, directions, per_sample);
}

std::vector<float> Sampler::directions_on_host(const detail::ProgramVariant& variant,
                                               const detail::ValidatedParams& valid,
                                               const std::vector<Vec3>& directions, const PerSampleInputs& per_sample)
{
    const std::uint64_t count = directions.size();
    if (count == 0)
        throw InvalidArgument("directions", "0 entries", "at least one direction");
    validate(per_sample, *valid, count);
    std::vector<float> result(count);
    translate_cl_errors([&] {
        std::uint64_t start = 0, chunk = fitted_capacity(max_alloc_, chunk_size_, count, 3);
        detail::retry_with_smaller_chunks(chunk, smallest_chunk, memory_retries_, [&](std::uint64_t capacity) {
            cl::Buffer dirs = detail::device_buffer(context_, CL_MEM_READ_ONLY, bytes(3 * capacity));
            cl::Buffer pdfs = detail::device_buffer(context_, CL_MEM_WRITE_ONLY, bytes(capacity));
            detail::ChunkInputs inputs(context_, per_sample, *valid, capacity);
            // The per-sample inputs' kinds and promises select the program, as in enqueue_pdf.
            detail::ProgramVariant chunk_variant =
                detail::variant_of(detail::ProgramKind::bulk, *valid, 0, inputs.buffers);
            chunk_variant.eval = variant.eval;
            while (start < count) {  // start: the first direction whose pdf is not read back
                std::uint64_t n = std::min(capacity, count - start);
                inputs.upload(queue_, per_sample, start, n, capacity);
                detail::ChunkInputs::write(queue_, dirs, detail::planar_units(directions, start, n, capacity));
                launch_directions(queue_, chunk_variant, valid, std::uint32_t(n), dirs, pdfs,
                                  std::uint32_t(capacity), inputs.buffers, nullptr);
                detail::read_and_wait(queue_, pdfs, 0, bytes(n), result.data() + start);
                start += n;
            }
        });
        return 0;
    });
    return result;
}

} // namespace ggxcl
