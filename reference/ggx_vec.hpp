// ggx_vec.hpp - the 3-vector of the ggxcl host reference and the few vector operations it uses.
#pragma once

#include <cmath>

namespace ggxref {

struct Vec3 {
    double x, y, z;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return (1.0 / length(a)) * a; }
// Mirror reflection of i about the unit normal m: o = 2 (i.m) m - i.
inline Vec3 reflect(const Vec3& i, const Vec3& m) { return 2.0 * dot(i, m) * m - i; }

// Some unit vector perpendicular to the unit vector n.
inline Vec3 any_perpendicular(const Vec3& n)
{
    return normalize(std::fabs(n.x) < 0.9 ? cross(n, {1.0, 0.0, 0.0}) : cross(n, {0.0, 1.0, 0.0}));
}

}  // namespace ggxref
