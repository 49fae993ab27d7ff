// native_vec.hpp - the float 3-vector of the native baseline and the few operations the samplers
// use (plain scalar code; the compiler is left to do what it can with it).
#pragma once

#include <cmath>

namespace ggxnative {

struct Vec3 {
    float x, y, z;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1.0f / length(a)) * a; }

// Mirror reflection of i about the unit normal m: o = 2 (i.m) m - i.
inline Vec3 reflect(Vec3 i, Vec3 m) { return (2.0f * dot(i, m)) * m - i; }

// The stretch of Heitz 2018 sec. 2: (ax wx, ay wy, wz).  Its length is t(w).
inline Vec3 stretch(Vec3 w, float ax, float ay) { return {ax * w.x, ay * w.y, w.z}; }

}  // namespace ggxnative
