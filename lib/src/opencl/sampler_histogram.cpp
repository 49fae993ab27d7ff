// sampler_histogram.cpp - Sampler::histogram: device-side binning of sample
// directions in launches of bounded size, 32-bit counts per launch summed
// into 64-bit counts on the host; the request is validated once, before
// the first launch.
#include <algorithm>
#include <numeric>

#include "cl_call.hpp"
#include "device_quirks.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"
#include "device_contract.hpp"
#include "histogram_bins.hpp"
#include "kernel_launch.hpp"
#include "queue_waits.hpp"
#include "validated_params.hpp"

namespace ggxcl {

namespace {

constexpr std::uint32_t samples_per_item = 64;
constexpr std::uint64_t samples_per_launch = 1u << 30;      // keeps every 32-bit bin count below 2^32
constexpr std::uint64_t samples_per_index_pass = 1u << 22;  // the bin indices of one pass: 16 MiB
constexpr std::uint64_t smallest_pass = 1024;  // samples; out of memory below it is an error

std::string histogram_options(const cl::Device& device, const SampleParams& params, int bins_z, int bins_phi,
                              Field direction)
{
    detail::ProgramVariant variant = detail::variant_of(detail::ProgramKind::histogram, params, 0);
    variant.bins = {bins_z, bins_phi, direction == Field::m};
    return detail::build_options(device, variant);
}

} // namespace

// One histogram request: its program and the launches of
// either strategy of kernels/ggx_histogram.cl.
struct Sampler::HistogramRun {
    Sampler& sampler;
    const SampleParams& params;
    const SampleRange& range;
    std::size_t bins;
    std::string options;
    cl::Buffer counts;   // bins + 2 counters (non-finite, invalid), zeroed before each pass
    cl::Buffer indices;  // CPU strategy: a pass's bin indices
    std::uint32_t counters = 1;  // CPU strategy: work-groups of one that count a pass

    // pass: the most samples one pass counts (the CPU strategy's index buffer holds that many).
    HistogramRun(Sampler& s, const SampleParams& p, const SampleRange& r, std::size_t bin_count, std::string opts,
                 bool by_indices, std::uint64_t pass)
        : sampler(s), params(p), range(r), bins(bin_count), options(std::move(opts))
    {
        counts = detail::device_buffer(sampler.context_, CL_MEM_READ_WRITE, (bins + 2) * sizeof(cl_uint));
        if (!by_indices)
            return;
        const std::uint64_t n = std::min(pass, range.count);
        indices = detail::device_buffer(sampler.context_, CL_MEM_READ_WRITE, n * sizeof(cl_uint));
        if (detail::kernel_writes_look_uninitialized(sampler.device_)) {
            const std::vector<cl_uint> zeros(n, 0u);
            detail::write_and_wait(sampler.queue_, indices, 0, n * sizeof(cl_uint), zeros.data());
        }
        counters = 4 * sampler.compute_units_;
    }

    void set_sample_args(cl::Kernel& k, std::uint64_t start, std::uint64_t n) const
    {
        k.setArg(detail::arg_seed, cl_ulong(range.seed));
        k.setArg(detail::arg_first, cl_ulong(range.first + start));
        k.setArg(detail::arg_count, cl_uint(n));
        k.setArg(detail::arg_stride, cl_uint(samples_per_item));  // the histogram kernels' samples per work-item
        detail::set_param_args(k, 4, params, {});
    }

    void zero_counts() const
    {
        // Zeroed by a write, not clEnqueueFillBuffer: Oclgrind's checker takes
        // filled memory as uninitialized (shown by a minimal kernel in test_oclgrind).
        const std::vector<cl_uint> zeros(bins + 2, 0u);
        detail::write_and_wait(sampler.queue_, counts, 0, (bins + 2) * sizeof(cl_uint), zeros.data());
    }

    std::vector<cl_uint> read_counts() const
    {
        std::vector<cl_uint> host(bins + 2);
        detail::read_and_wait(sampler.queue_, counts, 0, (bins + 2) * sizeof(cl_uint), host.data());
        return host;
    }

    // Local-memory atomics per work-group (GPUs).
    std::vector<cl_uint> count_in_groups(std::uint64_t start, std::uint64_t n) const
    {
        KernelLease lease = sampler.kernel(detail::program_file(detail::ProgramKind::histogram), "ggx_histogram", options);
        zero_counts();
        set_sample_args(*lease, start, n);
        lease->setArg(detail::arg_outputs, counts);
        const std::size_t group = sampler.work_group_size();
        std::size_t groups = (n + group * samples_per_item - 1) / (group * samples_per_item);
        detail::before_launch();
        sampler.queue_.enqueueNDRangeKernel(*lease, cl::NullRange, cl::NDRange(groups * group), cl::NDRange(group));
        return read_counts();
    }

    // Bin indices by a vectorizable kernel, then counted without atomics (CPUs).
    std::vector<cl_uint> count_by_indices(std::uint64_t start, std::uint64_t n) const
    {
        zero_counts();
        auto make = [&](const std::string& name) {
            KernelLease lease = sampler.kernel(detail::program_file(detail::ProgramKind::histogram), name, options);
            set_sample_args(*lease, start, n);
            lease->setArg(detail::arg_outputs, indices);
            return lease;
        };
        detail::launch_split(sampler.queue_, sampler.work_group_size(), make, "ggx_histogram_bins", cl_uint(n), nullptr);
        const std::uint32_t per_counter = std::uint32_t((n + counters - 1) / counters);
        KernelLease count = sampler.kernel(detail::program_file(detail::ProgramKind::histogram), "ggx_histogram_count", options);
        count->setArg(detail::count_arg_bins, indices);
        count->setArg(detail::count_arg_count, cl_uint(n));
        count->setArg(detail::count_arg_per_item, cl_uint(per_counter));
        count->setArg(detail::count_arg_counts, counts);
        detail::before_launch();
        sampler.queue_.enqueueNDRangeKernel(*count, cl::NullRange, cl::NDRange((n + per_counter - 1) / per_counter),
                                            cl::NDRange(1));
        return read_counts();
    }
};

Histogram Sampler::histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                             Field direction)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    const SampleParams& unit = *valid;
    return detail::translate_cl_errors([&] {
        detail::check_histogram_bins(bins_z, bins_phi, direction, local_mem_);
        const bool cpu = cpu_;
        const std::size_t bins = std::size_t(bins_z) * bins_phi;
        const std::string options = histogram_options(device_, unit, bins_z, bins_phi, direction);
        Histogram result{bins_z, bins_phi, std::vector<std::uint64_t>(bins, 0), 0, 0};
        // Passes of at most `pass` samples, halved when the device runs out of memory: the counts are
        // integers, the same however the range is cut.
        std::uint64_t start = 0, pass = std::min(cpu ? samples_per_index_pass : samples_per_launch, range.count);
        detail::retry_with_smaller_chunks(pass, smallest_pass, memory_retries_, [&](std::uint64_t capacity) {
            HistogramRun run(*this, unit, range, bins, options, cpu, capacity);
            while (start < range.count) {  // start: the first sample not counted
                const std::uint64_t n = std::min(capacity, range.count - start);
                std::vector<cl_uint> counts = cpu ? run.count_by_indices(start, n) : run.count_in_groups(start, n);
                for (std::size_t b = 0; b < bins; ++b)
                    result.counts[b] += counts[b];
                result.non_finite += counts[bins];
                result.invalid += counts[bins + 1];
                start += n;
            }
        });
        return result;
    });
}

} // namespace ggxcl
