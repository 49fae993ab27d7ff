// sample_compare.cpp - sample-by-sample comparison of device and reference.
#include "sample_compare.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <doctest/doctest.h>

namespace ggxtest {

namespace {

bool finite(const ggxref::Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

ggxref::Vec3 as_double(const ggxcl::Vec3& v)
{
    return {v.x, v.y, v.z};
}

} // namespace

double angle_between(const ggxref::Vec3& a, const ggxref::Vec3& b)
{
    ggxref::Vec3 c = ggxref::cross(a, b);
    return std::atan2(ggxref::length(c), ggxref::dot(a, b));
}

void compare_samples(const ggxcl::SampleSet& d, std::uint64_t seed, const ReferenceSampler& reference, bool is_ndf,
                     const std::string& label, SampleErrors& errors, ggxcl::Sequence sequence)
{
    for (std::size_t j = 0; j < d.count; ++j) {
        std::array<double, 2> u = reference_uniforms(sequence, seed, j);
        ggxref::Sample r = reference(j, u[0], u[1]);
        ggxref::Vec3 dm = as_double(d.m_at(j)), dob = as_double(d.o_at(j));
        bool all_finite = finite(dm) && finite(dob) && finite(r.m) && finite(r.o) && std::isfinite(d.pdf_m[j]) &&
                          std::isfinite(d.pdf_o[j]) && std::isfinite(d.weight[j]) && std::isfinite(r.pdf_m) &&
                          std::isfinite(r.pdf_o) && std::isfinite(r.weight);
        if (!all_finite) {
            ++errors.non_finite;
            continue;
        }
        double angle = std::max(angle_between(dm, r.m), angle_between(dob, r.o));
        if (angle > errors.worst_angle) {
            errors.worst_angle = angle;
            errors.worst_where = label + " u=(" + std::to_string(u[0]) + "," + std::to_string(u[1]) + ")";
        }
        errors.angle.push_back(angle);
        errors.pdf.push_back(relative_error(d.pdf_m[j], r.pdf_m));
        if (!is_ndf || std::fabs(ggxref::dot(r.o, r.m)) >= 1e-2)
            errors.pdf.push_back(relative_error(d.pdf_o[j], r.pdf_o));
        errors.weight.push_back(std::fabs(d.weight[j] - r.weight));
    }
}

void check_sample_errors(const std::string& name, const SampleErrors& errors, const ErrorBound& angle,
                         const ErrorBound& pdf, const ErrorBound& weight)
{
    CAPTURE(errors.worst_where);
    CHECK(errors.non_finite == 0);
    check_errors(name, angle, errors.angle);
    check_errors(name, pdf, errors.pdf);
    check_errors(name, weight, errors.weight);
}

} // namespace ggxtest
