// native_vectorized.cpp - the furnace job with its loop vectorized by the host compiler: the
// same device functions as native_jobs.hpp under `#pragma omp simd` (-fopenmp-simd), built with
// -fno-math-errno so that a square root is one instruction the vectorizer can widen.  The guards
// and the dispatch are selects and constants, so the whole sample is straight-line code.
#include <thread>
#include <vector>

#include "native_jobs.hpp"

namespace ggxnative {
namespace {

template <int method>
double block_sum(const Setup& setup, std::uint64_t begin, std::uint64_t end)
{
    const ggx_vec3 i = setup_view(setup);
    const float ax = setup.alpha_x, ay = setup.alpha_y;
    const std::uint64_t seed = setup.seed;
    double sum = 0.0;
#pragma omp simd reduction(+ : sum)
    for (std::uint64_t k = begin; k < end; ++k)
        sum += tangent_sample<method>(seed, k, i, ax, ay).weight;
    return sum;
}

using BlockSum = double (*)(const Setup&, std::uint64_t, std::uint64_t);

BlockSum pick_block_sum(int method)
{
    switch (method) {
#define GGXNATIVE_BLOCK_SUM(ID, identifier, name, ...) \
    case GGX_METHOD_##ID:                         \
        return block_sum<GGX_METHOD_##ID>;
        GGX_METHOD_LIST(GGXNATIVE_BLOCK_SUM)
#undef GGXNATIVE_BLOCK_SUM
    }
    return nullptr;
}

}  // namespace

double furnace_vectorized(const Setup& setup)
{
    const BlockSum sum_of = pick_block_sum(setup.method);
    const int threads = setup.threads < 1 ? 1 : setup.threads;
    const std::uint64_t count = setup.count, blocks = (count + furnace_block - 1) / furnace_block;
    std::vector<double> sums(blocks, 0.0);
    auto work = [&](int t) {
        for (std::uint64_t b = blocks * t / threads; b < blocks * (t + 1) / threads; ++b)
            sums[b] = sum_of(setup, b * furnace_block, (b + 1) * furnace_block < count ? (b + 1) * furnace_block : count);
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
