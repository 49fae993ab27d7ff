// test_histogram_bins.cpp - the histogram's binning (kernels/ggx_histogram_bin.h)
// without atan2: the phi bin from a polynomial angle and the side of the
// edge nearest to it.  Over 1e8 caps directions it gives the bin of the
// atan2 formula it replaces for every direction not within 1e-6 rad of a
// bin edge (where either is right to float rounding), at 2^16 phi bins too
// (the library's limit), and few differ at
// all; directions exactly on the quarter-turn edges, the pole and -0 fall
// where atan2 puts them; and the two counting strategies (local atomics,
// for GPUs; bin indices then counted, for CPUs) give the same counts.
// The comparisons build the binning header and their own kernels alone: the
// histogram kernels' local counters at 24 x 2^16 bins (6 MB) would exceed
// every GPU's local memory.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "device_fixture.hpp"
#include "ggx_contract.h"

namespace {

const char* compare_kernel = R"CL(
#include "ggx_samplers.h"
#include "ggx_histogram_bin.h"

// The bin of the atan2 formula the library used before.
uint atan2_bin(ggx_vec3 d)
{
    float phi = atan2(d.y, d.x);
    phi = phi < 0.0f ? phi + GGX_TWO_PI : phi;
    int zb = clamp((int)floor(0.5f * (d.z + 1.0f) * GGX_BINS_Z), 0, GGX_BINS_Z - 1);
    int pb = clamp((int)floor(phi * (GGX_BINS_PHI / GGX_TWO_PI)), 0, GGX_BINS_PHI - 1);
    return (uint)(zb * GGX_BINS_PHI + pb);
}

// Directions of caps samples [first, first + n) (alpha 0.4, view 50 degrees); the
// differing ones are counted and the first 4096 stored as (x, y, z, new bin, old bin).
__kernel void compare_bins(ulong first, __global uint* differ, __global float* found)
{
    ulong j = first + get_global_id(0);
    float u1, u2;
    ggx_uniforms(7ul, j, &u1, &u2);
    ggx_sample s = ggx_sample_caps(ggx_vec3_make(0.76604444f, 0.0f, 0.64278761f), 0.4f, 0.4f, u1, u2);
    uint now = ggx_bin_of(s.o), before = atan2_bin(s.o);
    if (now != before) {
        uint k = atomic_inc(differ);
        if (k < 4096u) {
            found[5 * k] = s.o.x; found[5 * k + 1] = s.o.y; found[5 * k + 2] = s.o.z;
            found[5 * k + 3] = (float)now; found[5 * k + 4] = (float)before;
        }
    }
}

__kernel void bins_of(__global const float* d, __global uint* bins)
{
    uint j = get_global_id(0);
    bins[2 * j] = ggx_bin_of(ggx_vec3_make(d[3 * j], d[3 * j + 1], d[3 * j + 2]));
    bins[2 * j + 1] = atan2_bin(ggx_vec3_make(d[3 * j], d[3 * j + 1], d[3 * j + 2]));
}
)CL";

// The comparison kernels with nz x nphi bins: the samplers, the binning header and nothing else.
cl::Program compare_program(int nz, int nphi)
{
    auto& s = ggxtest::sampler();
    std::string options = "-DGGX_BINS_Z=" + std::to_string(nz) + " -DGGX_BINS_PHI=" + std::to_string(nphi);
    return ggxcl::build_user_program(s.context(), s.device(), compare_kernel, options);
}

// Angular distance of (x, y) from the nearest of nphi edges, in double.
double distance_to_edge(double x, double y, int nphi)
{
    const double width = 2.0 * M_PI / nphi;
    double phi = std::atan2(y, x);
    phi = phi < 0 ? phi + 2.0 * M_PI : phi;
    double r = std::fmod(phi, width);
    return std::min(r, width - r);
}

} // namespace

TEST_CASE("1e8 caps directions: the new phi bin is atan2's except within 1e-6 rad of an edge")
{
    auto& s = ggxtest::sampler();
    // 2^16 phi bins, the most the library allows: the nearest-edge rule at its narrowest bins.
    for (auto [nphi, total] : {std::pair<int, std::uint64_t>{64, 100000000}, {36, 100000000}, {65536, 1u << 24}}) {
        CAPTURE(nphi);
        cl::Program program = compare_program(24, nphi);
        cl::Kernel k(program, "compare_bins");
        cl::Buffer differ(s.context(), CL_MEM_READ_WRITE, 4), found(s.context(), CL_MEM_READ_WRITE, 5 * 4096 * 4);
        const cl_uint zero = 0;
        s.queue().enqueueWriteBuffer(differ, CL_TRUE, 0, 4, &zero);
        k.setArg(1, differ);
        k.setArg(2, found);
        const std::uint64_t launch = 1u << 24;
        for (std::uint64_t first = 0; first < total; first += launch) {
            k.setArg(0, cl_ulong(first));
            s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(std::min(launch, total - first)));
        }
        cl_uint count = 0;
        s.queue().enqueueReadBuffer(differ, CL_TRUE, 0, 4, &count);
        std::vector<float> d(5 * 4096);
        s.queue().enqueueReadBuffer(found, CL_TRUE, 0, d.size() * 4, d.data());
        MESSAGE("nphi " << nphi << ": " << count << " of " << total << " directions binned differently from atan2");
        CHECK(count <= total / 100000 * std::max(1, nphi / 64));  // 1e-5 of the samples per 64 bins at most
        double farthest = 0;
        int new_exact = 0, old_exact = 0;  // agreeing with the double-precision phi bin of the float direction
        for (std::size_t k2 = 0; k2 < std::min<std::size_t>(count, 4096); ++k2) {
            const float* r = &d[5 * k2];
            farthest = std::max(farthest, distance_to_edge(r[0], r[1], nphi));
            double phi = std::atan2(double(r[1]), double(r[0]));
            phi = phi < 0 ? phi + 2.0 * M_PI : phi;
            const int exact = int(std::floor(phi / (2.0 * M_PI) * nphi)) % nphi;
            new_exact += int(r[3]) % nphi == exact;
            old_exact += int(r[4]) % nphi == exact;
        }
        MESSAGE("of those, the exact bin: new " << new_exact << ", atan2 " << old_exact);
        CHECK(farthest < 1e-6);
        CHECK(new_exact >= old_exact);
    }
}

TEST_CASE("the comparison program at 24 x 2^16 bins holds its two kernels alone: no histogram kernel")
{
    const std::string names = compare_program(24, 65536).getInfo<CL_PROGRAM_KERNEL_NAMES>();
    CAPTURE(names);
    CHECK((names == "compare_bins;bins_of" || names == "bins_of;compare_bins"));
}

TEST_CASE("directions on the quarter-turn edges, the pole and -0 fall where atan2 puts them")
{
    auto& s = ggxtest::sampler();
    const int nz = 4, nphi = 64;
    std::vector<float> dirs;
    for (float z : {0.0f, 0.5f})
        for (auto xy : std::vector<std::pair<float, float>>{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, -0.0f}, {-1, -0.0f},
                                                             {0, 0}, {-0.0f, 1}, {-0.0f, -1}})
            for (float v : {xy.first, xy.second, z})
                dirs.push_back(v);
    const std::size_t n = dirs.size() / 3;
    cl::Buffer in(s.context(), dirs.begin(), dirs.end(), true), out(s.context(), CL_MEM_READ_WRITE, 8 * n);
    cl::Kernel k(compare_program(nz, nphi), "bins_of");
    k.setArg(0, in);
    k.setArg(1, out);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<cl_uint> bins(2 * n);
    s.queue().enqueueReadBuffer(out, CL_TRUE, 0, 8 * n, bins.data());
    for (std::size_t j = 0; j < n; ++j) {
        CAPTURE(dirs[3 * j]);
        CAPTURE(dirs[3 * j + 1]);
        CHECK(bins[2 * j] == bins[2 * j + 1]);
    }
    // The quarter turns start bins 0, 16, 32 and 48 of the z bin.
    CHECK(bins[0] % nphi == 0);
    CHECK(bins[2] % nphi == 16);
    CHECK(bins[4] % nphi == 32);
    CHECK(bins[6] % nphi == 48);
}

TEST_CASE("both counting strategies give the same counts: local atomics and bin indices counted")
{
    auto& s = ggxtest::sampler();
    const int nz = 16, nphi = 32;
    ggxcl::SampleParams p{ggxcl::Method::caps, 0.3f, 0.5f, ggxcl::view_from_angles(50, 20)};
    const ggxcl::SampleRange range{3, 1000, 300000};
    ggxcl::Histogram library = s.histogram(p, range, nz, nphi);  // the device's own strategy
    // The local-atomics kernel, built with the options the runtime uses for this request.
    const std::string options = "-DGGX_METHOD=3 -DGGX_BINS_Z=16 -DGGX_BINS_PHI=32 -DGGX_BIN_M=0 -DGGX_ISOTROPIC=0 "
                                "-DGGX_BELOW_HORIZON=0 -DGGX_GUARDS=1 -DGGX_NORMAL_IS_Z=1 -DGGX_WORLD_SPACE=0";
    cl::Program program =
        ggxcl::build_user_program(s.context(), s.device(), ggxcl::kernel_source("ggx_histogram.cl"), options);
    cl::Kernel k(program, "ggx_histogram");
    const ggxcl::Vec3 v = ggxcl::normalized(p).view;
    // Work-groups of 64, or of what the device allows this kernel (rusticl on llvmpipe: 32).
    const std::uint32_t per_item = 64,
                        group = std::uint32_t(std::min<std::size_t>(64, k.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(s.device())));
    // The kernel's counters live in local memory: nz x nphi is small enough for any device.
    const cl_ulong local_bytes = (nz * nphi + 2) * sizeof(cl_uint);
    REQUIRE(local_bytes <= s.device().getInfo<CL_DEVICE_LOCAL_MEM_SIZE>());
    cl::Buffer counts(s.context(), CL_MEM_READ_WRITE, (nz * nphi + 1) * 4);
    std::vector<cl_uint> host(nz * nphi + 1, 0);
    s.queue().enqueueWriteBuffer(counts, CL_TRUE, 0, host.size() * 4, host.data());
    // The positions of kernels/ggx_contract.h, as the runtime sets them.
    k.setArg(GGX_ARG_SEED, cl_ulong(range.seed));
    k.setArg(GGX_ARG_FIRST, cl_ulong(range.first));
    k.setArg(GGX_ARG_COUNT, cl_uint(range.count));
    k.setArg(GGX_ARG_STRIDE, cl_uint(per_item));
    const float uniforms[GGX_PARAM_UNIFORM_COUNT] = {v.x, v.y, v.z, p.alpha_x, p.alpha_y, 0.0f, 0.0f, 1.0f, 0.0f};
    for (int a = 0; a < GGX_PARAM_ARG_COUNT; ++a)
        if (a < GGX_PARAM_UNIFORM_COUNT)
            k.setArg(GGX_ARG_PARAMS + a, uniforms[a]);
        else
            k.setArg(GGX_ARG_PARAMS + a, cl::Buffer());  // no per-sample inputs
    k.setArg(GGX_ARG_OUTPUTS, counts);
    const std::size_t groups = (range.count + group * per_item - 1) / (group * per_item);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(groups * group), cl::NDRange(group));
    s.queue().enqueueReadBuffer(counts, CL_TRUE, 0, host.size() * 4, host.data());
    std::size_t differ = 0;
    for (std::size_t b = 0; b < library.counts.size(); ++b)
        differ += library.counts[b] != host[b];
    CHECK(differ == 0);
    CHECK(library.total() == range.count);
    CHECK(library.non_finite == host.back());
    CHECK(s.histogram(p, {4, 1000, 300000}, nz, nphi).counts != library.counts);  // control: the counts see the seed
}
