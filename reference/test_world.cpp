// test_world.cpp - the Duff et al. basis is orthonormal and right-handed with
// n as its third axis for normals over the whole sphere (n = -z included), and
// world-space samples are the tangent-space samples carried by that basis.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "ggx_world.hpp"

namespace {

using namespace ggxref;

std::vector<Vec3> sphere_normals()
{
    std::vector<Vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0, -0.0}};
    normals.back() = normalize({1e-9, 0, -1});
    for (int k = 0; k < 200; ++k) {
        double z = -1.0 + (k + 0.5) / 100.0, phi = 2.399963 * k;  // Fibonacci sphere
        double r = std::sqrt(1.0 - z * z);
        normals.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return normals;
}

}  // namespace

TEST_CASE("Duff basis: orthonormal, right-handed, third axis n, everywhere on the sphere")
{
    for (const Vec3& n : sphere_normals()) {
        Basis b = duff_basis(n);
        CAPTURE(n.x);
        CAPTURE(n.y);
        CAPTURE(n.z);
        CHECK(std::fabs(dot(b.t, b.t) - 1.0) < 1e-12);
        CHECK(std::fabs(dot(b.b, b.b) - 1.0) < 1e-12);
        CHECK(std::fabs(dot(b.t, b.b)) < 1e-12);
        CHECK(std::fabs(dot(b.t, n)) < 1e-12);
        CHECK(std::fabs(dot(b.b, n)) < 1e-12);
        Vec3 c = cross(b.t, b.b);
        CHECK(length(c - n) < 1e-12);
        Vec3 v{0.3, -0.4, 0.5};
        CHECK(length(to_world(b, to_local(b, v)) - v) < 1e-12);
    }
}

TEST_CASE("world-space samples: in the basis of n they are the tangent-space samples")
{
    Vec3 n = normalize({0.3, -0.5, 0.6});
    Basis b = duff_basis(n);
    Vec3 local_view = normalize({0.4, 0.1, 0.8});
    Params world{0.3, 0.3, to_world(b, local_view), n};
    Params local{0.3, 0.3, local_view, {0, 0, 1}};
    for (Method method : all_methods) {
        Sample w = sample_world(method, world, 0.37, 0.81);
        Sample t = sample(method, local, 0.37, 0.81);
        CAPTURE(method_name(method));
        CHECK(dot(w.o, n) == doctest::Approx(t.o.z).epsilon(1e-12));
        CHECK(std::fabs(dot(w.o, w.o) - 1.0) < 1e-12);
        CHECK(w.pdf_o == doctest::Approx(t.pdf_o).epsilon(1e-9));
        if (method != Method::caps_iso)  // caps-iso turns its cap by a half-turn, not by this basis
            CHECK(length(to_local(b, w.o) - t.o) < 1e-12);
    }
}
