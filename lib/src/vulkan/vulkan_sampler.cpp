// vulkan_sampler.cpp - VulkanSampler: a request validated as Sampler's are
// (detail::validated_request), its variant (variant_of_host_inputs) built as
// a bulk shader (kernels/ggx_bulk.comp or .hlsl), and the range drawn chunk
// by chunk through two mapped buffers: the per-sample inputs' planes and the
// requested fields' planes; the pdf and BSDF value of given directions
// through the pdf shader (ggx_pdf.comp or .hlsl).  The histogram, furnace
// and stress jobs: vulkan_jobs.cpp.
#include "backend_factories.hpp"
#include "planar_inputs.hpp"
#include "validated_params.hpp"
#include "vulkan_sampler_state.hpp"

namespace ggxcl {

namespace {

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

} // namespace

VulkanSampler::VulkanSampler(const std::string& selector, ShaderLanguage language) : state_(std::make_unique<State>())
{
    const VulkanDeviceInfo info = select_vulkan_device(selector);
    state_->vulkan = detail::vulkan_instance();
    state_->language = language;
    state_->compute = detail::translate_vulkan_errors(info.name, [&] {
        return std::make_unique<detail::VulkanCompute>(state_->vulkan, info);
    });
}

namespace detail {

std::unique_ptr<Backend> open_vulkan_backend(const std::string& selector, ShaderLanguage language)
{
    return std::make_unique<VulkanSampler>(selector, language);
}

} // namespace detail

VulkanSampler::~VulkanSampler() = default;
VulkanSampler::VulkanSampler(VulkanSampler&&) noexcept = default;
VulkanSampler& VulkanSampler::operator=(VulkanSampler&&) noexcept = default;

const VulkanDeviceInfo& VulkanSampler::device() const { return state_->compute->info(); }
std::string VulkanSampler::device_name() const { return device().label(); }
ShaderLanguage VulkanSampler::language() const { return state_->language; }
std::size_t VulkanSampler::shaders_built() const
{
    const std::lock_guard lock(state_->calls);
    return state_->pipelines.size();
}

std::size_t VulkanSampler::shaders_from_disk() const
{
    const std::lock_guard lock(state_->calls);
    return state_->from_disk;
}

std::uint64_t VulkanSampler::chunk_size() const { return state_->chunk_size; }
std::size_t VulkanSampler::work_group_size() const { return detail::group_size; }

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
    generate_chunk_views(params, range, fields, [&](const SampleView& chunk, std::uint64_t offset) {
        detail::copy_into(all, chunk, offset, fields, params.eta != 0.0f);
    }, per_sample);
    return all;
}

void VulkanSampler::generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                    const ChunkSink& sink, const PerSampleInputs& per_sample)
{
    generate_chunk_views(params, range, fields, [&](const SampleView& view, std::uint64_t offset) {
        sink(detail::copy_of(view, fields, params.eta != 0.0f), offset);
    }, per_sample);
}

void VulkanSampler::generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                         const ChunkViewSink& sink, const PerSampleInputs& per_sample)
{
    const detail::ValidatedParams valid = detail::validated_request(params, range, fields, per_sample);
    const SampleParams& p = *valid;
    const bool dielectric = p.eta != 0.0f;
    const detail::ProgramVariant variant =
        detail::variant_of_host_inputs(detail::ProgramKind::bulk, p, detail::write_mask(fields), per_sample);
    State& s = *state_;
    const std::lock_guard lock(s.calls);
    const std::uint64_t out_per_sample = output_floats(fields, dielectric), in_per_sample = input_floats(per_sample);
    const std::uint64_t capacity = s.capacity(std::max(out_per_sample, in_per_sample), range.count);
    detail::translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.pipeline(variant);
        detail::MappedBuffer inputs = s.compute->buffer(in_per_sample * capacity);
        detail::MappedBuffer outputs = s.compute->buffer(out_per_sample * capacity);
        detail::BulkRequest request = detail::request_of(p, range.seed);
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
            detail::put_inputs(per_sample, done, n, capacity, inputs, request);
            request.first_lo = detail::low_word(range.first + done);
            request.first_hi = detail::high_word(range.first + done);
            request.count = std::uint32_t(n);
            s.dispatch(pipeline, request, n, inputs, outputs);
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
    const std::uint64_t count = directions.size();
    if (count == 0)
        throw InvalidArgument("directions", "0 entries", "at least one direction");
    validate(per_sample, *valid, count);
    detail::ProgramVariant variant = detail::variant_of_host_inputs(detail::ProgramKind::bulk, *valid, 0, per_sample);
    variant.eval = eval;
    State& s = *state_;
    const std::lock_guard lock(s.calls);
    const std::uint64_t in_per_sample = input_floats(per_sample) + 3, capacity = s.capacity(in_per_sample, count);
    std::vector<float> result(count);
    detail::translate_vulkan_errors(device().name, [&] {
        const vk::raii::Pipeline& pipeline = s.pipeline(variant, "ggx_pdf");
        detail::MappedBuffer inputs = s.compute->buffer(in_per_sample * capacity), outputs = s.compute->buffer(capacity);
        detail::BulkRequest request = detail::request_of(*valid, 0);
        request.stride = std::uint32_t(capacity);
        for (std::uint64_t done = 0; done < count;) {
            const std::uint64_t n = std::min(capacity, count - done);
            request.o_at = detail::put_inputs(per_sample, done, n, capacity, inputs, request);
            const std::vector<float> planes = detail::planar_units(directions, done, n, capacity);
            std::memcpy(inputs.data + request.o_at, planes.data(), planes.size() * sizeof(float));
            request.count = std::uint32_t(n);
            s.dispatch(pipeline, request, n, inputs, outputs);
            std::copy_n(outputs.data, n, result.begin() + std::ptrdiff_t(done));
            done += n;
        }
    });
    return result;
}

} // namespace ggxcl
