// sample_agreement.cpp - Vulkan's samples against OpenCL's (sample_agreement.hpp).
#include "sample_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <doctest/doctest.h>

#include "error_bounds.hpp"
#include "sample_compare.hpp"

namespace ggxvk {

namespace {

ggxref::Vec3 in_double(const ggxcl::Vec3& v)
{
    return {double(v.x), double(v.y), double(v.z)};
}

double quantile(std::vector<double> values, double q)
{
    if (values.empty())
        return 0.0;
    const std::size_t k = std::size_t(q * double(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

} // namespace

Agreement sample_agreement(const ggxcl::SampleSet& tested, const ggxcl::SampleSet& opencl,
                           const std::vector<float>& tested_pdf, const std::vector<float>& opencl_pdf)
{
    std::vector<double> angles, pdfs, recomputed;
    Agreement a;
    for (std::size_t j = 0; j < opencl.count; ++j) {
        for (float v : {tested.pdf_o[j], tested.weight[j], tested.o[j]})
            a.non_finite += std::isfinite(v) ? 0 : 1;
        angles.push_back(ggxtest::angle_between(in_double(tested.m_at(j)), in_double(opencl.m_at(j))));
        angles.push_back(ggxtest::angle_between(in_double(tested.o_at(j)), in_double(opencl.o_at(j))));
        pdfs.push_back(ggxtest::relative_error(tested.pdf_o[j], opencl.pdf_o[j]));
        if (!tested_pdf.empty()) {
            a.non_finite += std::isfinite(tested_pdf[j]) ? 0 : 1;
            recomputed.push_back(ggxtest::relative_error(tested_pdf[j], opencl_pdf[j]));
        }
    }
    a.angle_99 = quantile(angles, 0.99);
    a.angle_max = angles.empty() ? 0.0 : *std::max_element(angles.begin(), angles.end());
    a.pdf_99 = quantile(pdfs, 0.99);
    a.recomputed_pdf_99 = quantile(recomputed, 0.99);
    return a;
}

Agreement worst_of(const Agreement& a, const Agreement& b)
{
    return {std::max(a.angle_99, b.angle_99), std::max(a.angle_max, b.angle_max), std::max(a.pdf_99, b.pdf_99),
            std::max(a.recomputed_pdf_99, b.recomputed_pdf_99), a.non_finite + b.non_finite};
}

std::string describe(const Agreement& a)
{
    std::ostringstream text;
    text.precision(2);
    text << "angle 99% " << a.angle_99 << " rad, max " << a.angle_max << "; pdf_o relative 99% " << a.pdf_99
         << "; the pdf function's 99% " << a.recomputed_pdf_99 << "; non-finite " << a.non_finite;
    return text.str();
}

void check_agreement_bounds(const Agreement& a, const std::string& label)
{
    INFO(label, ": ", describe(a));
    CHECK(a.non_finite == 0);
    CHECK(a.angle_99 <= 1e-5);
    CHECK(a.angle_max <= 2e-3);
    CHECK(a.pdf_99 <= 1e-4);
    CHECK(a.recomputed_pdf_99 <= 1e-4);
}

} // namespace ggxvk
