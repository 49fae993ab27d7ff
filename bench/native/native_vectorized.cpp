// native_vectorized.cpp - the hand-vectorized "ceiling" of the native baseline: the white-furnace
// weight sum of isotropic caps sampling (Dupuy & Benyoub 2023) with GCC vector extensions of one
// register (16 lanes with AVX-512, 8 otherwise), Philox2x32-10 on vectors, the reduced sincos of
// kernels/ggx_sincos.h, nothing written.  Same uniforms and weights as the scalar
// run(caps, furnace_sum), up to float rounding.
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#include "native_baseline.hpp"

namespace ggxnative {
namespace {

// One vector register's width: wider generic vectors are split by the
// compiler and spill (on AVX2, 16 lanes ran no faster than scalar code).
#if defined(__AVX512F__)
#define GGXNATIVE_VECTOR_BYTES 64
constexpr int lanes = 16;
#else
#define GGXNATIVE_VECTOR_BYTES 32
constexpr int lanes = 8;
#endif
typedef float vfloat __attribute__((vector_size(GGXNATIVE_VECTOR_BYTES)));
typedef std::uint32_t vuint __attribute__((vector_size(GGXNATIVE_VECTOR_BYTES)));
typedef std::int32_t vint __attribute__((vector_size(GGXNATIVE_VECTOR_BYTES)));  // what comparisons return
typedef std::uint64_t vulong __attribute__((vector_size(GGXNATIVE_VECTOR_BYTES)));

constexpr std::uint64_t block = 4096;  // weights are summed per aligned block, blocks in order

vuint lane_indices()
{
    vuint v{};
    for (int l = 0; l < lanes; ++l)
        v[l] = std::uint32_t(l);
    return v;
}
const vuint iota = lane_indices();

vfloat splat(float x) { return vfloat{} + x; }

// Per-lane square root; with -fno-math-errno GCC emits one vector sqrt for the loop.
vfloat vsqrt(vfloat x)
{
    vfloat r;
    for (int l = 0; l < lanes; ++l)
        r[l] = std::sqrt(x[l]);
    return r;
}

vfloat vmax(vfloat a, vfloat b) { return a > b ? a : b; }
vfloat vmin(vfloat a, vfloat b) { return a < b ? a : b; }

// 32x32 -> 64-bit products of every lane of a with m, as low and high words.  Seen as half as
// many 64-bit lanes, a holds the even lanes in the low halves and the odd lanes in the high halves:
// both products are 32x32 -> 64 multiplies of 64-bit lanes (vpmuludq).
void mulhilo(vuint a, std::uint32_t m, vuint& lo, vuint& hi)
{
    const vulong wide = (vulong)a;
    const vulong even = (wide & 0xffffffffull) * std::uint64_t(m);
    const vulong odd = (wide >> 32) * std::uint64_t(m);
    lo = (vuint)((even & 0xffffffffull) | (odd << 32));
    hi = (vuint)((even >> 32) | (odd & 0xffffffff00000000ull));
}

// Philox2x32-10 (Salmon et al. 2011) on `lanes` counters {c0, c1} with one key; returns both words.
void philox_words(vuint c0, vuint c1, std::uint32_t key, vuint& w0, vuint& w1)
{
    for (int round = 0; round < 10; ++round) {
        vuint lo, hi;
        mulhilo(c0, 0xD256D193u, lo, hi);
        c0 = hi ^ c1 ^ key;
        c1 = lo;
        key += 0x9E3779B9u;
    }
    w0 = c0;
    w1 = c1;
}

// The top 24 bits of each word times 2^-24.
vfloat word_to_unit(vuint w) { return __builtin_convertvector((vint)(w >> 8), vfloat) * 5.9604644775390625e-8f; }

// sin(2 pi u), cos(2 pi u) for u in [0, 1] as kernels/ggx_sincos.h computes them (same
// reduction and coefficients): q = 4u, j = rint(q), f = q - j exact; polynomials in f^2 for the
// quarter turn (pi/2) f, then the pair swapped and negated by j mod 4.
void sincos_2pi(vfloat u, vfloat& s, vfloat& c)
{
    const vfloat q = 4.0f * u;
    // Round to nearest (even) for 0 <= q < 2^22 by adding and removing 1.5 * 2^23, lane-wise.
    volatile float magic_value = 12582912.0f;  // volatile: the compiler may not fold (q + m) - m into q
    const float magic = magic_value;
    const vfloat j = (q + magic) - magic;
    const vfloat f = q - j, x = f * f;
    vfloat ps = (-4.602149129e-03f * x + 7.968020439e-02f) * x - 6.459634900e-01f;
    ps = x * ps - 4.371138829e-08f;
    const vfloat sf = f * 1.570796371e+00f + f * ps;
    const vfloat pc = ((9.067399078e-04f * x - 2.086152695e-02f) * x + 2.536692619e-01f) * x - 1.233700514e+00f;
    const vfloat cf = pc * x + 1.0f;
    const vint quarter = __builtin_convertvector(j, vint);
    const vint odd = (quarter & 1) != 0, negate_s = (quarter & 2) != 0, negate_c = ((quarter + 1) & 2) != 0;
    const vfloat s_turned = odd ? cf : sf, c_turned = odd ? sf : cf;
    s = negate_s ? -s_turned : s_turned;
    c = negate_c ? -c_turned : c_turned;
}

// What every sample of one view shares: alpha, i, t(i), the stretched view v and the weight
// factor (iz + t) / (2 iz), so that weight = G2 (iz + t) / (2 iz) = oz (iz + t) / (t oz + t(o) iz).
struct View {
    float alpha, ix, iy, iz, ti, vx, vy, vz, weight_scale;
};

View make_view(float alpha, const float view[3])
{
    View w{alpha, view[0], view[1], view[2], 0, 0, 0, 0, 0};
    const float sx = alpha * w.ix, sy = alpha * w.iy;
    w.ti = std::sqrt(sx * sx + sy * sy + w.iz * w.iz);
    w.vx = sx / w.ti, w.vy = sy / w.ti, w.vz = w.iz / w.ti;
    w.weight_scale = (w.iz + w.ti) / (2.0f * w.iz);
    return w;
}

// Furnace weights of `lanes` samples from their uniforms (Dupuy & Benyoub 2023, sec. 3).
vfloat caps_weights(const View& w, vfloat u1, vfloat u2)
{
    // Reflected direction c uniform on the cap z in (-vz, 1] (Listing 3).
    const vfloat z = (1.0f - u2) * (1.0f + w.vz) - w.vz;
    const vfloat sin_theta = vsqrt(vmin(vmax(1.0f - z * z, splat(0.0f)), splat(1.0f)));
    vfloat sin_phi, cos_phi;
    sincos_2pi(u1, sin_phi, cos_phi);
    // Half vector h = c + v, unstretched and normalized: m = normalize(alpha hx, alpha hy, hz).
    const vfloat mx0 = w.alpha * (sin_theta * cos_phi + w.vx);
    const vfloat my0 = w.alpha * (sin_theta * sin_phi + w.vy);
    const vfloat mz0 = z + w.vz;
    const vfloat inv_len = 1.0f / vsqrt(mx0 * mx0 + my0 * my0 + mz0 * mz0);
    const vfloat mx = mx0 * inv_len, my = my0 * inv_len, mz = mz0 * inv_len;
    // o = 2 (i.m) m - i, t(o), and G2 (iz + t) / (2 iz) = oz (iz + t) / (t oz + t(o) iz) for oz > 0.
    const vfloat twice_dot = 2.0f * (w.ix * mx + w.iy * my + w.iz * mz);
    const vfloat ox = twice_dot * mx - w.ix, oy = twice_dot * my - w.iy, oz = twice_dot * mz - w.iz;
    const vfloat to = vsqrt(w.alpha * w.alpha * (ox * ox + oy * oy) + oz * oz);
    const vfloat weight = 2.0f * w.iz * oz / (w.ti * oz + to * w.iz) * w.weight_scale;
    return oz > 0.0f ? weight : splat(0.0f);
}

// The weight sum of samples [begin, end) of one block, `lanes` at a time.
double block_sum(std::uint64_t seed, const View& w, std::uint64_t begin, std::uint64_t end)
{
    vfloat sum = splat(0.0f);
    for (std::uint64_t base = begin; base < end; base += lanes) {
        const vuint c0 = std::uint32_t(base) + iota;
        const vuint c1 = std::uint32_t(base >> 32) - (vuint)(c0 < std::uint32_t(base));  // carry
        vuint w0, w1;
        philox_words(c0, c1, std::uint32_t(seed), w0, w1);
        const vfloat weights = caps_weights(w, word_to_unit(w0), word_to_unit(w1));
        const vint inside = (vint)iota < vint{} + int(end - base < lanes ? end - base : lanes);
        sum += inside ? weights : splat(0.0f);
    }
    double total = 0.0;
    for (int l = 0; l < lanes; ++l)
        total += sum[l];
    return total;
}

}  // namespace

double furnace_caps_vectorized(std::uint64_t seed, std::uint64_t count, float alpha, const float view[3],
                               int threads)
{
    if (!(view[2] > 0.0f))
        return 0.0;  // no reflection from below the horizon
    const View w = make_view(alpha, view);
    threads = threads < 1 ? 1 : threads;
    const std::uint64_t blocks = (count + block - 1) / block;
    std::vector<double> sums(blocks, 0.0);
    auto work = [&](int t) {
        for (std::uint64_t b = blocks * t / threads; b < blocks * (t + 1) / threads; ++b)
            sums[b] = block_sum(seed, w, b * block, (b + 1) * block < count ? (b + 1) * block : count);
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(work, t);
    work(0);
    for (std::thread& worker : workers)
        worker.join();
    double total = 0.0;
    for (double s : sums)
        total += s;
    return total;
}

}  // namespace ggxnative
