// device_albedo.hpp - the weights of every cell's samples on the device, on
// this program's own context and queue, two ways: the ggxcl runtime's
// sampler fills our buffer (Sampler::enqueue, per-sample views and roughness
// that our kernel wrote), which our kernel reduces; and our own kernel
// calling the sampler from the device headers.  Sample j of cell c is sample
// c * samples_per_cell + j of the seed's stream in both.
#pragma once

#include <cstdint>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "albedo_grid.hpp"

namespace albedo {

// Per cell: the sum of the weights and of their squares (added in double
// from float sums of blocks of 64 samples).
struct CellSums {
    std::vector<double> sum, sum_of_squares;
};

struct MethodSums {
    CellSums runtime, in_kernel;
    bool same_bits = true;  // every block sum of the two ways identical
};

class DeviceAlbedo {
public:
    static constexpr std::uint32_t block = 64;

    // samples_per_cell: a multiple of `block`.
    DeviceAlbedo(const cl::Context& context, const cl::Device& device, std::uint32_t samples_per_cell);

    MethodSums run(ggxcl::Method method, std::uint64_t seed);

private:
    struct RowBuffers {
        cl::Buffer views, alphas, weights, sums, squares, inline_sums, inline_squares;
    };
    void enqueue_row(const cl::Program& program, ggxcl::Method method, std::uint64_t seed, std::uint32_t row);
    void add_row(std::uint32_t row, MethodSums& out);

    cl::Context context_;
    cl::Device device_;
    cl::CommandQueue queue_;
    ggxcl::Sampler sampler_;
    std::uint32_t per_cell_;
    std::uint32_t row_samples_;
    cl::Buffer cells_;
    RowBuffers row_;
};

} // namespace albedo
