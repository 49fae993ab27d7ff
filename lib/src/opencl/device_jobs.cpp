// device_jobs.cpp - the bench's jobs on an OpenCL Sampler
// (ggxcl/benchmark.hpp): into device buffers made once, each run a launch
// timed by its event's profiling and by wall clock around launch and wait.
#include <chrono>

#include "backend_factories.hpp"
#include "device_contract.hpp"
#include "device_quirks.hpp"
#include "kernel_launch.hpp"
#include "validated_params.hpp"
#include "chunk_inputs.hpp"
#include "program_variant.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/sampler.hpp"

namespace ggxcl::detail {

namespace {

using benchmark::Job;

// The caller's per-sample arrays in device buffers (planes of stride n), with the promises they keep.
DeviceInputs device_inputs(Sampler& sampler, const SampleParams& params, const PerSampleInputs& in)
{
    const std::uint64_t n = in.views.size();
    ChunkInputs buffers(sampler.context(), in, params, n);
    buffers.upload(sampler.queue(), in, 0, n, n);
    return buffers.buffers;
}

// The profiled duration of a finished command in ns; -1 when the driver gives none.
double profiled_ns(const cl::Event& done)
{
    cl_ulong start = 0, end = 0;
    if (done.getProfilingInfo(CL_PROFILING_COMMAND_START, &start) != CL_SUCCESS ||
        done.getProfilingInfo(CL_PROFILING_COMMAND_END, &end) != CL_SUCCESS)
        return -1.0;
    return double(end) - double(start);
}

class OpenclJobs final : public benchmark::DeviceJobs {
public:
    OpenclJobs(Sampler& sampler, std::uint64_t count, const benchmark::JobInputs& inputs);
    bool runs(Job) const override { return true; }
    std::uint64_t samples(Job job) const override
    {
        return job == Job::world ? world_count_ : job == Job::per_sample ? per_sample_count_ : count_;
    }
    benchmark::RunTime run(Job job, const SampleParams& params, std::uint64_t seed) override;
    std::optional<benchmark::ProgramText> program(Job job, const SampleParams& params) const override;

private:
    cl::Event launch(Job job, const SampleParams& params, std::uint64_t seed);

    Sampler& sampler_;
    std::uint32_t count_, world_count_, per_sample_count_;
    DeviceOutputs write_out_, write_o_out_, world_out_;  // write_o_out_: write_out_'s buffers
    DeviceInputs world_in_, per_sample_in_;
    cl::Buffer sums_;
    cl::Kernel store_;
};

OpenclJobs::OpenclJobs(Sampler& sampler, std::uint64_t count, const benchmark::JobInputs& inputs)
    : sampler_(sampler), count_(std::uint32_t(count)), world_count_(std::uint32_t(inputs.world.views.size())),
      per_sample_count_(std::uint32_t(inputs.per_sample.views.size()))
{
    if (count < 1 || count > (1u << 31))
        throw InvalidArgument("count", std::to_string(count), "1 .. 2^31 samples per run");
    const cl::Context& context = sampler.context();
    const std::size_t most = std::max({count_, world_count_, per_sample_count_});
    write_out_.m = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * most * sizeof(float));
    write_out_.pdf_m = cl::Buffer(context, CL_MEM_WRITE_ONLY, most * sizeof(float));
    write_o_out_.o = write_out_.m;  // the same bytes: 3 planes and 1
    write_o_out_.pdf_o = write_out_.pdf_m;
    world_out_.o = write_out_.m;
    // Weights and their squares, and a dielectric's reflected weights (Sampler::enqueue_furnace).
    sums_ = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * sampler.furnace_items(count_) * sizeof(float));
    if (world_count_ > 0)
        world_in_ = device_inputs(sampler, world_job_params(SampleParams{}), inputs.world);
    if (per_sample_count_ > 0)
        per_sample_in_ = device_inputs(sampler, SampleParams{}, inputs.per_sample);
    cl::Program store(context, kernel_source("ggx_store.cl"));
    store.build({sampler.device()});
    store_ = cl::Kernel(store, "store_only");
}

cl::Event OpenclJobs::launch(Job job, const SampleParams& params, std::uint64_t seed)
{
    cl::CommandQueue& queue = sampler_.queue();
    const SampleRange range{seed, 0, samples(job)};
    switch (job) {
    case Job::write:  // with or without the guards (params.guards)
        return sampler_.enqueue(queue, params, range, write_out_);
    case Job::write_o:
        return sampler_.enqueue(queue, params, range, write_o_out_);
    case Job::furnace: {  // as Sampler::furnace runs it: unguarded, rerun with guards only on a NaN sum
        SampleParams unguarded = params;
        unguarded.guards = false;
        return sampler_.enqueue_furnace(queue, unguarded, range, sums_);
    }
    case Job::world:
        return sampler_.enqueue(queue, world_job_params(params), range, world_out_, 0, world_in_);
    case Job::per_sample:
        return sampler_.enqueue(queue, params, range, write_out_, 0, per_sample_in_);
    case Job::store: {
        store_.setArg(0, write_out_.m);
        store_.setArg(1, write_out_.pdf_m);
        store_.setArg(2, cl_uint(count_));
        store_.setArg(3, cl_float(seed));
        cl::Event done;
        queue.enqueueNDRangeKernel(store_, cl::NullRange, cl::NDRange(count_), cl::NullRange, nullptr, &done);
        return done;
    }
    }
    return {};
}

benchmark::RunTime OpenclJobs::run(Job job, const SampleParams& params, std::uint64_t seed)
{
    if ((job == Job::world && world_count_ == 0) || (job == Job::per_sample && per_sample_count_ == 0))
        throw InvalidArgument("job inputs", "none", "per-sample inputs for the world and per-sample jobs");
    const auto start = std::chrono::steady_clock::now();
    const cl::Event done = launch(job, params, seed);
    done.wait();
    const double wall_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    return {profiled_ns(done), wall_ns};
}

// The variant and options as the Sampler's launches make them; the quirk options are build_program's.
std::optional<benchmark::ProgramText> OpenclJobs::program(Job job, const SampleParams& params) const
{
    if (job != Job::write && job != Job::write_o && job != Job::furnace)
        return std::nullopt;
    SampleParams p = *validated(params);
    p.guards = p.guards && job != Job::furnace;  // the furnace runs unguarded, as launch() does
    const FieldSet fields = job == Job::write     ? FieldSet{Field::m, Field::pdf_m}
                            : job == Job::write_o ? FieldSet{Field::o, Field::pdf_o}
                                                  : FieldSet{Field::weight};
    const ProgramVariant variant =
        variant_of(job == Job::furnace ? ProgramKind::furnace : ProgramKind::bulk, p, write_mask(fields));
    const cl::Device& device = sampler_.device();
    return benchmark::ProgramText{program_file(variant.kind), job == Job::furnace ? "ggx_furnace_bulk" : "ggx_sample_bulk",
                                  build_options(device, variant) + device_quirk_options(device)};
}

} // namespace

std::unique_ptr<benchmark::DeviceJobs> opencl_device_jobs(Backend& sampler, std::uint64_t count,
                                                          benchmark::JobInputs inputs)
{
    return std::make_unique<OpenclJobs>(static_cast<Sampler&>(sampler), count, inputs);
}

} // namespace ggxcl::detail
