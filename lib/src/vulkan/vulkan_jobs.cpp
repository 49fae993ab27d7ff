// vulkan_jobs.cpp - VulkanSampler's jobs that return more than samples: a
// histogram runs the histogram shader (kernels/ggx_histogram.comp or .hlsl)
// in passes whose 32-bit counts are summed on the host; the furnace the
// furnace shader (ggx_furnace.comp or .hlsl), whose partial sums are added
// on the host as OpenCL's are; the stability map's cases the stress shader
// (ggx_stress.comp or .hlsl).
#include "furnace_sums.hpp"
#include "histogram_bins.hpp"
#include "validated_params.hpp"
#include "stress_request.hpp"
#include "vulkan_sampler_state.hpp"

namespace ggxcl {

namespace {

constexpr std::uint32_t histogram_per_item = 64;           // samples per invocation of the histogram shader
constexpr std::uint64_t histogram_pass = 1u << 30;         // keeps every 32-bit count below 2^32

} // namespace

Histogram VulkanSampler::histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                                   Field direction)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    detail::check_histogram_bins(bins_z, bins_phi, direction, device().max_shared_memory);
    detail::ProgramVariant variant = detail::variant_of(detail::ProgramKind::histogram, *valid, 0);
    variant.bins = {bins_z, bins_phi, direction == Field::m};
    const std::size_t bins = std::size_t(bins_z) * std::size_t(bins_phi);
    Histogram result{bins_z, bins_phi, std::vector<std::uint64_t>(bins, 0), 0, 0};
    State& s = *state_;
    const std::lock_guard lock(s.calls);
    detail::translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.pipeline(variant);
        detail::MappedBuffer unused = s.compute->buffer(1), counts = s.compute->buffer(bins + 2);
        detail::BulkRequest request = detail::request_of(*valid, range.seed);
        request.stride = histogram_per_item;
        std::vector<std::uint32_t> pass_counts(bins + 2);
        for (std::uint64_t start = 0; start < range.count;) {
            const std::uint64_t n = std::min(histogram_pass, range.count - start);
            std::memset(counts.data, 0, (bins + 2) * sizeof(std::uint32_t));
            request.first_lo = detail::low_word(range.first + start);
            request.first_hi = detail::high_word(range.first + start);
            request.count = std::uint32_t(n);
            const std::uint64_t groups = (n + detail::group_size * histogram_per_item - 1) / (detail::group_size * histogram_per_item);
            s.dispatch(pipeline, request, groups * detail::group_size, unused, counts);
            std::memcpy(pass_counts.data(), counts.data, pass_counts.size() * sizeof(std::uint32_t));
            for (std::size_t b = 0; b < bins; ++b)
                result.counts[b] += pass_counts[b];
            result.non_finite += pass_counts[bins];
            result.invalid += pass_counts[bins + 1];
            start += n;
        }
    });
    return result;
}

// Dispatches of the furnace shader whose partial sums are added in double:
// each unguarded first, and again with the guards if a sum is not finite.
FurnaceSums VulkanSampler::furnace(const SampleParams& params, const SampleRange& range)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    State& s = *state_;
    const std::lock_guard lock(s.calls);
    const std::uint64_t per_item = detail::furnace_per_item, planes = detail::furnace_sum_planes(*valid);
    // Samples per dispatch: a multiple of the samples per invocation, their sums within one storage buffer.
    const std::uint64_t items_fit = device().max_storage_buffer_range / sizeof(float) / planes;
    const std::uint64_t per_dispatch = std::max(per_item, std::min(s.chunk_size.load(), items_fit * per_item) / per_item * per_item);
    // The unguarded program, and the guarded one built only when a sum is not finite.
    SampleParams unguarded = *valid, guarded = *valid;
    unguarded.guards = false;
    guarded.guards = true;
    const unsigned weights = detail::write_mask({Field::weight});
    const detail::ProgramVariant variants[] = {detail::variant_of(detail::ProgramKind::furnace, unguarded, weights),
                                               detail::variant_of(detail::ProgramKind::furnace, guarded, weights)};
    FurnaceSums total;
    total.count = range.count;
    detail::translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline* pipelines[] = {&s.pipeline(variants[0]), nullptr};
        detail::MappedBuffer unused = s.compute->buffer(1), sums = s.compute->buffer(planes * (per_dispatch / per_item));
        detail::BulkRequest request = detail::request_of(*valid, range.seed);
        for (std::uint64_t done = 0; done < range.count;) {
            const std::uint64_t n = std::min(per_dispatch, range.count - done), items = (n + per_item - 1) / per_item;
            request.first_lo = detail::low_word(range.first + done);
            request.first_hi = detail::high_word(range.first + done);
            request.count = std::uint32_t(n);
            request.stride = std::uint32_t(items);
            for (int guards = 0; guards < 2; ++guards) {
                if (!pipelines[guards])
                    pipelines[guards] = &s.pipeline(variants[guards]);
                s.dispatch(*pipelines[guards], request, items, unused, sums);
                if (detail::add_furnace_partial_sums(sums.data, std::size_t(items), std::size_t(planes), total,
                                                     guards == 1))
                    break;
            }
            done += n;
        }
    });
    return total;
}

std::vector<float> VulkanSampler::stress(const StressRequest& stress, const std::vector<float>& in, std::uint32_t count)
{
    const detail::StressPlanes planes = detail::checked_stress(stress, in, count);
    const std::uint64_t in_planes = planes.in, out_planes = planes.out;
    State& s = *state_;
    const std::lock_guard lock(s.calls);
    const detail::ShaderDefines defines = {{"GGX_METHOD", detail::method_id(stress.method)},
                                           {"GGX_GUARDS", stress.guards ? 1 : 0},
                                           {"GGX_DIELECTRIC", stress.dielectric ? 1 : 0}};
    const std::uint64_t capacity = s.capacity(in_planes, count);
    std::vector<float> out(out_planes * count);
    detail::translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.shader_pipeline("ggx_stress", defines, stress.user);
        detail::MappedBuffer inputs = s.compute->buffer(in_planes * capacity);
        detail::MappedBuffer outputs = s.compute->buffer(out_planes * capacity);
        detail::BulkRequest request{};
        for (std::uint64_t start = 0; start < count;) {  // the planes of cases [start, start + n) packed
            const std::uint64_t n = std::min<std::uint64_t>(capacity, count - start);
            for (std::uint64_t k = 0; k < in_planes; ++k)
                std::copy_n(in.begin() + std::ptrdiff_t(k * count + start), n, inputs.data + k * n);
            request.count = std::uint32_t(n);
            s.dispatch(pipeline, request, n, inputs, outputs);
            for (std::uint64_t k = 0; k < out_planes; ++k)
                std::copy_n(outputs.data + k * n, n, out.begin() + std::ptrdiff_t(k * count + start));
            start += n;
        }
    });
    return out;
}

} // namespace ggxcl
