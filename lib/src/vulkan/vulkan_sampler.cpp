// vulkan_sampler.cpp - VulkanSampler: a request validated as Sampler's are
// (detail::validated_request), its variant (variant_of_host_inputs) built as
// a bulk shader (kernels/ggx_bulk.comp or .hlsl), and the range drawn chunk
// by chunk through two mapped buffers: the per-sample inputs' planes and the
// requested fields' planes.  A histogram runs the histogram shader
// (kernels/ggx_histogram.comp or .hlsl) in passes whose 32-bit counts are
// summed on the host; the furnace the furnace shader (ggx_furnace.comp or
// .hlsl), whose partial sums are added on the host as OpenCL's are.
#include <algorithm>
#include <cstring>
#include <map>

#include "device_contract.hpp"
#include "furnace_sums.hpp"
#include "histogram_bins.hpp"
#include "planar_inputs.hpp"
#include "program_variant.hpp"
#include "spirv_compile.hpp"
#include "validated_params.hpp"
#include "vulkan_compute.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/vulkan.hpp"

namespace ggxcl {

namespace {

constexpr std::uint32_t group_size = 64;  // every device runs 128 invocations per work-group
constexpr std::uint32_t histogram_per_item = 64;           // samples per invocation of the histogram shader
constexpr std::uint64_t histogram_pass = 1u << 30;         // keeps every 32-bit count below 2^32

// The push constants of the bulk shader, from the list both sides read.
struct BulkRequest {
    using uint = std::uint32_t;
    GGX_BULK_REQUEST_MEMBERS
};
static_assert(sizeof(BulkRequest) == GGX_BULK_REQUEST_WORDS * 4, "ggx_contract.h: the push constants are 32-bit words");

std::uint32_t low_word(std::uint64_t v) { return std::uint32_t(v); }
std::uint32_t high_word(std::uint64_t v) { return std::uint32_t(v >> 32); }

// Floats per sample of the requested fields, and of the per-sample inputs.
std::uint64_t output_floats(FieldSet fields, bool dielectric)
{
    std::uint64_t n = 0;
    for (Field f : all_fields)
        if (fields.has(f))
            n += std::uint64_t(field_columns(f, dielectric));
    return n;
}

std::uint64_t input_floats(const PerSampleInputs& in)
{
    return (in.views.empty() ? 0 : 3) + (in.alphas.empty() ? 0 : 2) + (in.normals.empty() ? 0 : 3) +
           (in.uniforms.empty() ? 0 : in.lobe_uniforms.empty() ? 2 : 3);
}

// vk::SystemError (a std::system_error) as ggxcl's errors.
template <typename Call>
auto translate_vulkan_errors(const std::string& device, Call&& call)
{
    try {
        return call();
    } catch (const vk::DeviceLostError& e) {
        throw DeviceError("the Vulkan device '" + device + "' was lost (" + e.what() +
                          "); the results of this call are incomplete");
    } catch (const vk::SystemError& e) {
        throw DeviceError("a Vulkan call on '" + device + "' failed: " + e.what());
    }
}

void refuse_user_sampler(const SampleParams& params)
{
    if (params.method == Method::user || params.user_sampler)
        throw InvalidArgument("method", "user", "a built-in method on Vulkan (user samplers run on OpenCL for now)");
}

// Entries [done, done + n) of the caller's per-sample inputs as planes of
// stride `capacity`, one input after another in `inputs`, their offsets in
// `request`; returns the floats used.
std::uint32_t put_inputs(const PerSampleInputs& in, std::uint64_t done, std::uint64_t n, std::uint64_t capacity,
                         detail::MappedBuffer& inputs, BulkRequest& request)
{
    std::uint32_t at = 0;
    auto put = [&](std::uint32_t& offset, const std::vector<float>& planes) {
        offset = at;
        std::memcpy(inputs.data + at, planes.data(), planes.size() * sizeof(float));
        at += std::uint32_t(planes.size());
    };
    if (!in.views.empty()) put(request.view_at, detail::planar_units(in.views, done, n, capacity));
    if (!in.alphas.empty()) put(request.alpha_at, detail::planar_pairs(in.alphas, done, n, capacity));
    if (!in.normals.empty()) put(request.normal_at, detail::planar_units(in.normals, done, n, capacity));
    if (!in.uniforms.empty()) put(request.uniforms_at, detail::planar_uniforms(in, done, n, capacity));
    return at;
}

// The push constants every shader reads of a request: its seed and uniform parameters.
BulkRequest request_of(const SampleParams& p, std::uint64_t seed)
{
    BulkRequest request{};
    request.seed_lo = low_word(seed);
    request.seed_hi = high_word(seed);
    request.view_x = p.view.x, request.view_y = p.view.y, request.view_z = p.view.z;
    request.alpha_x = p.alpha_x, request.alpha_y = p.alpha_y;
    request.normal_x = p.normal.x, request.normal_y = p.normal.y, request.normal_z = p.normal.z;
    request.eta = p.eta;
    return request;
}

} // namespace

struct VulkanSampler::State {
    std::shared_ptr<detail::VulkanInstance> vulkan;
    std::unique_ptr<detail::VulkanCompute> compute;
    ShaderLanguage language = ShaderLanguage::glsl;
    std::uint64_t chunk_size = 1u << 20;
    std::map<std::string, vk::raii::Pipeline> pipelines;  // by program and defines
    std::size_t from_disk = 0;

    // The pipeline of shader `program` (kernels/<program>.comp or .hlsl) built with `defines`.
    const vk::raii::Pipeline& shader_pipeline(const std::string& program, detail::ShaderDefines defines)
    {
        defines.emplace_back("GGX_GROUP_SIZE", long(group_size));
        std::string key = program;
        for (const auto& [name, value] : defines)
            key += " " + name + "=" + std::to_string(value);
        auto found = pipelines.find(key);
        if (found != pipelines.end())
            return found->second;
        const std::string file = program + (language == ShaderLanguage::hlsl ? ".hlsl" : ".comp");
        const detail::CompiledShader shader = detail::compile_shader(language, file, defines);
        from_disk += shader.from_disk ? 1 : 0;
        return pipelines.emplace(key, compute->pipeline(shader.spirv)).first->second;
    }

    // A request variant's: the shader of its kind with its switches.
    const vk::raii::Pipeline& pipeline(const detail::ProgramVariant& variant)
    {
        return shader_pipeline(std::string("ggx_") + detail::program_kind_name(variant.kind),
                               detail::variant_define_list(variant));
    }

    // Samples per chunk: the chunk size, within one storage buffer of the device.
    std::uint64_t capacity(std::uint64_t floats_per_sample) const
    {
        const std::uint64_t range = compute->info().max_storage_buffer_range / sizeof(float);
        return std::max<std::uint64_t>(1, std::min(chunk_size, range / std::max<std::uint64_t>(floats_per_sample, 1)));
    }
};

VulkanSampler::VulkanSampler(const std::string& selector, ShaderLanguage language) : state_(std::make_unique<State>())
{
    const VulkanDeviceInfo info = select_vulkan_device(selector);
    state_->vulkan = detail::vulkan_instance();
    state_->language = language;
    state_->compute = translate_vulkan_errors(info.name, [&] {
        return std::make_unique<detail::VulkanCompute>(state_->vulkan, info);
    });
}

VulkanSampler::~VulkanSampler() = default;
VulkanSampler::VulkanSampler(VulkanSampler&&) noexcept = default;
VulkanSampler& VulkanSampler::operator=(VulkanSampler&&) noexcept = default;

const VulkanDeviceInfo& VulkanSampler::device() const { return state_->compute->info(); }
std::string VulkanSampler::device_name() const { return device().label(); }
ShaderLanguage VulkanSampler::language() const { return state_->language; }
std::size_t VulkanSampler::shaders_built() const { return state_->pipelines.size(); }
std::size_t VulkanSampler::shaders_from_disk() const { return state_->from_disk; }
std::uint64_t VulkanSampler::chunk_size() const { return state_->chunk_size; }

void VulkanSampler::set_chunk_size(std::uint64_t samples)
{
    if (samples < 1 || samples > (1ull << 31))
        throw InvalidArgument("chunk size", std::to_string(samples), "1 .. 2^31 samples");
    state_->chunk_size = samples;
}

SampleSet VulkanSampler::generate(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                  const PerSampleInputs& per_sample)
{
    SampleSet all;
    all.count = range.count;
    const bool dielectric = params.eta != 0.0f;
    for (Field f : all_fields)
        if (fields.has(f))
            all.column_source(f).resize(std::size_t(field_columns(f, dielectric) * range.count));
    generate_chunk_views(params, range, fields, [&](const SampleView& chunk, std::uint64_t offset) {
        for (Field f : all_fields) {
            if (!fields.has(f))
                continue;
            for (int c = 0; c < field_columns(f, dielectric); ++c)
                std::copy_n(chunk.column_source(f) + c * chunk.stride, chunk.count,
                            all.column_source(f).begin() + std::ptrdiff_t(c * range.count + offset));
        }
    }, per_sample);
    return all;
}

void VulkanSampler::generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                    const ChunkSink& sink, const PerSampleInputs& per_sample)
{
    const bool dielectric = params.eta != 0.0f;
    SampleSet chunk;
    generate_chunk_views(params, range, fields, [&](const SampleView& view, std::uint64_t offset) {
        chunk.count = view.count;
        for (Field f : all_fields) {
            if (!fields.has(f))
                continue;
            std::vector<float>& planes = chunk.column_source(f);
            const int columns = field_columns(f, dielectric);
            planes.resize(std::size_t(columns) * view.count);
            for (int c = 0; c < columns; ++c)
                std::copy_n(view.column_source(f) + c * view.stride, view.count,
                            planes.begin() + std::ptrdiff_t(c * view.count));
        }
        sink(chunk, offset);
    }, per_sample);
}

void VulkanSampler::generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                         const ChunkViewSink& sink, const PerSampleInputs& per_sample)
{
    const detail::ValidatedParams valid = detail::validated_request(params, range, fields, per_sample);
    refuse_user_sampler(params);
    const SampleParams& p = *valid;
    const bool dielectric = p.eta != 0.0f;
    const detail::ProgramVariant variant =
        detail::variant_of_host_inputs(detail::ProgramKind::bulk, p, detail::write_mask(fields), per_sample);
    State& s = *state_;
    const std::uint64_t out_per_sample = output_floats(fields, dielectric), in_per_sample = input_floats(per_sample);
    const std::uint64_t capacity = s.capacity(std::max(out_per_sample, in_per_sample));
    translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.pipeline(variant);
        detail::MappedBuffer inputs = s.compute->buffer(in_per_sample * capacity);
        detail::MappedBuffer outputs = s.compute->buffer(out_per_sample * capacity);
        BulkRequest request = request_of(p, range.seed);
        request.stride = std::uint32_t(capacity);
        // Each field's and input's planes, one after another in their buffer.
        std::uint32_t at = 0;
        std::uint32_t* field_at[] = {&request.m_at, &request.o_at, &request.pdf_m_at,
                                     &request.pdf_o_at, &request.weight_at, &request.u_at};
        for (Field f : all_fields)
            if (fields.has(f))
                *field_at[int(f)] = at, at += std::uint32_t(field_columns(f, dielectric) * capacity);
        SampleView chunk;  // the planes in the mapped buffer, stride = capacity
        chunk.stride = capacity;
        for (Field f : all_fields)
            if (fields.has(f))
                chunk.column_source(f) = outputs.data + *field_at[int(f)];
        for (std::uint64_t done = 0; done < range.count;) {
            const std::uint64_t n = std::min(capacity, range.count - done);
            put_inputs(per_sample, done, n, capacity, inputs, request);
            request.first_lo = low_word(range.first + done);
            request.first_hi = high_word(range.first + done);
            request.count = std::uint32_t(n);
            const detail::DispatchShape shape =
                detail::dispatch_shape(n, group_size, device().max_work_groups_x, device().max_work_groups_y);
            request.row_width = shape.row_width;
            s.compute->dispatch(pipeline, &request, sizeof request, inputs, outputs, shape);
            chunk.count = n;
            sink(chunk, done);
            done += n;
        }
    });
}

std::vector<float> VulkanSampler::pdf(const SampleParams& params, const std::vector<Vec3>& directions,
                                      const PerSampleInputs& per_sample)
{
    return of_directions(params, directions, per_sample, false);
}

std::vector<float> VulkanSampler::eval(const SampleParams& params, const std::vector<Vec3>& directions,
                                       const PerSampleInputs& per_sample)
{
    return of_directions(params, directions, per_sample, true);
}

// The pdf shader (kernels/ggx_pdf.comp, .hlsl) over the directions, chunk by
// chunk: the per-sample inputs' planes, then the directions', in `inputs`.
std::vector<float> VulkanSampler::of_directions(const SampleParams& params, const std::vector<Vec3>& directions,
                                                const PerSampleInputs& per_sample, bool eval)
{
    const detail::ValidatedParams valid = detail::validated(params);
    refuse_user_sampler(params);
    const std::uint64_t count = directions.size();
    if (count == 0)
        throw InvalidArgument("directions", "0 entries", "at least one direction");
    validate(per_sample, *valid, count);
    detail::ProgramVariant variant = detail::variant_of_host_inputs(detail::ProgramKind::bulk, *valid, 0, per_sample);
    variant.eval = eval;
    State& s = *state_;
    const std::uint64_t in_per_sample = input_floats(per_sample) + 3, capacity = s.capacity(in_per_sample);
    std::vector<float> result(count);
    translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.shader_pipeline("ggx_pdf", detail::variant_define_list(variant));
        detail::MappedBuffer inputs = s.compute->buffer(in_per_sample * capacity), outputs = s.compute->buffer(capacity);
        BulkRequest request = request_of(*valid, 0);
        request.stride = std::uint32_t(capacity);
        for (std::uint64_t done = 0; done < count;) {
            const std::uint64_t n = std::min(capacity, count - done);
            request.o_at = put_inputs(per_sample, done, n, capacity, inputs, request);
            const std::vector<float> planes = detail::planar_units(directions, done, n, capacity);
            std::memcpy(inputs.data + request.o_at, planes.data(), planes.size() * sizeof(float));
            request.count = std::uint32_t(n);
            const detail::DispatchShape shape =
                detail::dispatch_shape(n, group_size, device().max_work_groups_x, device().max_work_groups_y);
            request.row_width = shape.row_width;
            s.compute->dispatch(pipeline, &request, sizeof request, inputs, outputs, shape);
            std::copy_n(outputs.data, n, result.begin() + std::ptrdiff_t(done));
            done += n;
        }
    });
    return result;
}

Histogram VulkanSampler::histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                                   Field direction)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    refuse_user_sampler(params);
    detail::check_histogram_bins(bins_z, bins_phi, direction, device().max_shared_memory);
    detail::ProgramVariant variant = detail::variant_of(detail::ProgramKind::histogram, *valid, 0);
    variant.bins = {bins_z, bins_phi, direction == Field::m};
    const std::size_t bins = std::size_t(bins_z) * std::size_t(bins_phi);
    Histogram result{bins_z, bins_phi, std::vector<std::uint64_t>(bins, 0), 0, 0};
    State& s = *state_;
    translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.pipeline(variant);
        detail::MappedBuffer unused = s.compute->buffer(1), counts = s.compute->buffer(bins + 2);
        BulkRequest request = request_of(*valid, range.seed);
        request.stride = histogram_per_item;
        std::vector<std::uint32_t> pass_counts(bins + 2);
        for (std::uint64_t start = 0; start < range.count;) {
            const std::uint64_t n = std::min(histogram_pass, range.count - start);
            std::memset(counts.data, 0, (bins + 2) * sizeof(std::uint32_t));
            request.first_lo = low_word(range.first + start);
            request.first_hi = high_word(range.first + start);
            request.count = std::uint32_t(n);
            const std::uint64_t groups = (n + group_size * histogram_per_item - 1) / (group_size * histogram_per_item);
            const detail::DispatchShape shape = detail::dispatch_shape(groups * group_size, group_size,
                                                                       device().max_work_groups_x, device().max_work_groups_y);
            request.row_width = shape.row_width;
            s.compute->dispatch(pipeline, &request, sizeof request, unused, counts, shape);
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
    refuse_user_sampler(params);
    State& s = *state_;
    const std::uint64_t per_item = detail::furnace_per_item, planes = detail::furnace_sum_planes(*valid);
    // Samples per dispatch: a multiple of the samples per invocation, their sums within one storage buffer.
    const std::uint64_t items_fit = device().max_storage_buffer_range / sizeof(float) / planes;
    const std::uint64_t per_dispatch = std::max(per_item, std::min(s.chunk_size, items_fit * per_item) / per_item * per_item);
    FurnaceSums total;
    total.count = range.count;
    translate_vulkan_errors(device().name, [&] {
        detail::MappedBuffer unused = s.compute->buffer(1), sums = s.compute->buffer(planes * (per_dispatch / per_item));
        BulkRequest request = request_of(*valid, range.seed);
        for (std::uint64_t done = 0; done < range.count;) {
            const std::uint64_t n = std::min(per_dispatch, range.count - done), items = (n + per_item - 1) / per_item;
            request.first_lo = low_word(range.first + done);
            request.first_hi = high_word(range.first + done);
            request.count = std::uint32_t(n);
            request.stride = std::uint32_t(items);
            const detail::DispatchShape shape =
                detail::dispatch_shape(items, group_size, device().max_work_groups_x, device().max_work_groups_y);
            request.row_width = shape.row_width;
            for (bool guards : {false, true}) {
                SampleParams p = *valid;
                p.guards = guards;
                const detail::ProgramVariant variant =
                    detail::variant_of(detail::ProgramKind::furnace, p, detail::write_mask({Field::weight}));
                s.compute->dispatch(s.pipeline(variant), &request, sizeof request, unused, sums, shape);
                if (detail::add_furnace_partial_sums(sums.data, std::size_t(items), std::size_t(planes), total, guards))
                    break;
            }
            done += n;
        }
    });
    return total;
}

std::vector<float> VulkanSampler::stress(Method method, bool guards, bool dielectric, const std::vector<float>& in,
                                         std::uint32_t count)
{
    if (method == Method::user)
        throw InvalidArgument("method", "user", "a built-in method on Vulkan (user samplers run on OpenCL for now)");
    const std::uint64_t in_planes = dielectric ? 12 : 10, out_planes = dielectric ? 11 : 10;
    if (in.size() != in_planes * count)
        throw InvalidArgument("stress inputs", std::to_string(in.size()) + " floats",
                              std::to_string(in_planes * count) + " (" + std::to_string(in_planes) + " planes of " +
                                  std::to_string(count) + " cases)");
    State& s = *state_;
    const detail::ShaderDefines defines = {{"GGX_METHOD", detail::method_id(method)}, {"GGX_GUARDS", guards ? 1 : 0},
                                           {"GGX_DIELECTRIC", dielectric ? 1 : 0}};
    const std::uint64_t capacity = s.capacity(in_planes);
    std::vector<float> out(out_planes * count);
    translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.shader_pipeline("ggx_stress", defines);
        detail::MappedBuffer inputs = s.compute->buffer(in_planes * capacity);
        detail::MappedBuffer outputs = s.compute->buffer(out_planes * capacity);
        BulkRequest request{};
        for (std::uint64_t start = 0; start < count;) {  // the planes of cases [start, start + n) packed
            const std::uint64_t n = std::min<std::uint64_t>(capacity, count - start);
            for (std::uint64_t k = 0; k < in_planes; ++k)
                std::copy_n(in.begin() + std::ptrdiff_t(k * count + start), n, inputs.data + k * n);
            request.count = std::uint32_t(n);
            const detail::DispatchShape shape =
                detail::dispatch_shape(n, group_size, device().max_work_groups_x, device().max_work_groups_y);
            request.row_width = shape.row_width;
            s.compute->dispatch(pipeline, &request, sizeof request, inputs, outputs, shape);
            for (std::uint64_t k = 0; k < out_planes; ++k)
                std::copy_n(outputs.data + k * n, n, out.begin() + std::ptrdiff_t(k * count + start));
            start += n;
        }
    });
    return out;
}

} // namespace ggxcl
