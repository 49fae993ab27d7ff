// device_jobs.cpp - benchmark::device_jobs: OpenCL's jobs (opencl/device_jobs.cpp), or any
// back end's through its Backend calls, timed by wall clock.
#include <chrono>

#include "backend_factories.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl::benchmark {

namespace {

class BackendJobs final : public DeviceJobs {
public:
    BackendJobs(Backend& backend, std::uint64_t count, JobInputs inputs)
        : backend_(backend), count_(count), inputs_(std::move(inputs)) {}

    bool runs(Job job) const override { return job != Job::store; }

    std::uint64_t samples(Job job) const override
    {
        return job == Job::world ? inputs_.world.views.size()
               : job == Job::per_sample ? inputs_.per_sample.views.size() : count_;
    }

    RunTime run(Job job, const SampleParams& params, std::uint64_t seed) override
    {
        const auto start = std::chrono::steady_clock::now();
        const SampleRange range{seed, 0, samples(job)};
        const auto copy_nothing = [](const SampleView&, std::uint64_t) {};
        switch (job) {
        case Job::write:
            backend_.generate_chunk_views(params, range, {Field::m, Field::pdf_m}, copy_nothing);
            break;
        case Job::write_o:
            backend_.generate_chunk_views(params, range, {Field::o, Field::pdf_o}, copy_nothing);
            break;
        case Job::furnace:
            backend_.furnace(params, range);
            break;
        case Job::world:
            backend_.generate_chunk_views(detail::world_job_params(params), range, {Field::o}, copy_nothing,
                                          inputs_.world);
            break;
        case Job::per_sample:
            backend_.generate_chunk_views(params, range, {Field::m, Field::pdf_m}, copy_nothing, inputs_.per_sample);
            break;
        case Job::store:
            throw InvalidArgument("job", "store", "a job of " + backend_.api_label() + " (store: OpenCL only)");
        }
        return {-1, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count()};
    }

    std::optional<ProgramText> program(Job, const SampleParams&) const override { return std::nullopt; }

private:
    Backend& backend_;
    std::uint64_t count_;
    JobInputs inputs_;
};

} // namespace

std::unique_ptr<DeviceJobs> device_jobs(Backend& backend, std::uint64_t count, JobInputs inputs)
{
    if (backend.api() == Api::opencl)
        return detail::opencl_device_jobs(backend, count, std::move(inputs));
    return std::make_unique<BackendJobs>(backend, count, std::move(inputs));
}

} // namespace ggxcl::benchmark
