// results.cpp - the members of the result types every back end returns (results.hpp).
#include "ggxcl/results.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>

namespace ggxcl {

std::vector<float>& SampleSet::column_source(Field field)
{
    std::vector<float>* planes[] = {&m, &o, &pdf_m, &pdf_o, &weight, &u};
    static_assert(std::size(planes) == all_fields.size());
    return *planes[static_cast<int>(field)];
}

const std::vector<float>& SampleSet::column_source(Field field) const
{
    return const_cast<SampleSet*>(this)->column_source(field);
}

const float*& SampleView::column_source(Field field)
{
    const float** planes[] = {&m, &o, &pdf_m, &pdf_o, &weight, &u};
    static_assert(std::size(planes) == all_fields.size());
    return *planes[int(field)];
}

const float* SampleView::column_source(Field field) const
{
    return const_cast<SampleView*>(this)->column_source(field);
}

SampleView view_of(const SampleSet& set)
{
    SampleView v;
    v.count = set.count;
    v.stride = set.count;
    for (Field f : all_fields)
        v.column_source(f) = set.column_source(f).empty() ? nullptr : set.column_source(f).data();
    return v;
}

std::uint64_t Histogram::total() const
{
    return std::accumulate(counts.begin(), counts.end(), non_finite + invalid);
}

double FurnaceSums::mean() const
{
    return count ? sum / double(count) : 0.0;
}

double FurnaceSums::reflectance() const
{
    return count ? reflected_sum / double(count) : 0.0;
}

double FurnaceSums::transmittance() const
{
    return count ? (sum - reflected_sum) / double(count) : 0.0;
}

double FurnaceSums::variance() const
{
    if (count < 2)
        return 0.0;
    double m = mean();
    return std::max(0.0, (sum_of_squares - double(count) * m * m) / double(count - 1));
}

} // namespace ggxcl
