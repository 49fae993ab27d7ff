// native_world_inputs.cpp - seeded random normals and views for the world_space_o job.
#include "native_world_inputs.hpp"

#include <cmath>
#include <random>

namespace ggxnative {

namespace {

// A unit vector from three standard normal deviates.
void random_direction(std::mt19937& rng, std::normal_distribution<float>& gauss, float v[3])
{
    for (int c = 0; c < 3; ++c) v[c] = gauss(rng);
    float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; ++c) v[c] /= length;
}

}  // namespace

void world_inputs(std::uint64_t count, std::vector<float>& normals, std::vector<float>& views)
{
    std::mt19937 rng(20231122);  // the seed ggx bench uses for its device inputs
    std::normal_distribution<float> gauss;
    normals.resize(3 * count);
    views.resize(3 * count);
    for (std::uint64_t j = 0; j < count; ++j) {
        float n[3], v[3];
        do
            random_direction(rng, gauss, n);
        while (n[2] < -0.999f);
        float cosine;
        do {
            random_direction(rng, gauss, v);
            cosine = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
            if (cosine < 0.0f)  // mirror into the side the normal points to
                for (int c = 0; c < 3; ++c) v[c] -= 2.0f * cosine * n[c];
            cosine = std::fabs(cosine);
        } while (cosine < 0.05f);
        for (int c = 0; c < 3; ++c) {
            normals[c * count + j] = n[c];
            views[c * count + j] = v[c];
        }
    }
}

}  // namespace ggxnative
