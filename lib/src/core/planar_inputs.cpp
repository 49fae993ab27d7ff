// planar_inputs.cpp - per-sample inputs as planes, and chunks' planes into host
// memory (planar_inputs.hpp).
#include "planar_inputs.hpp"

#include <algorithm>
#include <iterator>

namespace ggxcl::detail {

std::vector<float> planar_units(const std::vector<Vec3>& values, std::uint64_t start, std::uint64_t n,
                                std::uint64_t capacity)
{
    std::vector<float> planes(3 * capacity, 0.0f);
    for (std::uint64_t j = 0; j < n; ++j) {
        Vec3 v = unit_vector(values[start + j]);
        planes[j] = v.x;
        planes[capacity + j] = v.y;
        planes[2 * capacity + j] = v.z;
    }
    return planes;
}

std::vector<float> planar_pairs(const std::vector<std::array<float, 2>>& values, std::uint64_t start,
                                std::uint64_t n, std::uint64_t capacity)
{
    std::vector<float> planes(2 * capacity, 0.5f);
    for (std::uint64_t j = 0; j < n; ++j) {
        planes[j] = values[start + j][0];
        planes[capacity + j] = values[start + j][1];
    }
    return planes;
}

std::vector<float> planar_uniforms(const PerSampleInputs& in, std::uint64_t start, std::uint64_t n,
                                   std::uint64_t capacity)
{
    std::vector<float> planes = planar_pairs(in.uniforms, start, n, capacity);
    if (in.lobe_uniforms.empty())
        return planes;
    planes.resize(3 * capacity, 0.5f);
    std::copy_n(in.lobe_uniforms.begin() + std::ptrdiff_t(start), n, planes.begin() + std::ptrdiff_t(2 * capacity));
    return planes;
}

SampleSet copy_of(const SampleView& chunk, FieldSet fields, bool dielectric)
{
    SampleSet set;
    set.count = chunk.count;
    copy_into(set, chunk, 0, fields, dielectric);
    return set;
}

void copy_into(SampleSet& all, const SampleView& chunk, std::uint64_t offset, FieldSet fields, bool dielectric)
{
    for (Field f : all_fields) {
        if (!fields.has(f))
            continue;
        std::vector<float>& whole = all.column_source(f);
        const int columns = field_columns(f, dielectric);
        if (whole.empty())
            whole.resize(std::size_t(columns) * all.count);
        for (int c = 0; c < columns; ++c)
            std::copy_n(chunk.column_source(f) + c * chunk.stride, chunk.count,
                        whole.data() + c * all.count + offset);
    }
}

} // namespace ggxcl::detail
