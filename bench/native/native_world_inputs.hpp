// native_world_inputs.hpp - the per-sample inputs of the world_space_o job for ggx-native: the
// same planar unit normals and views, from the same seeded generator, as ggx bench builds for
// its device world job (apps/bench/bench_speed.cpp, random_job_inputs), rewritten here so that
// ggx-native does not link ggxcl.
#pragma once

#include <cstdint>
#include <vector>

namespace ggxnative {

// `count` unit normals over the sphere (away from the pole -z, where caps-iso is singular) and
// unit views at 0..87 degrees from them, planar (x block, y block, z block).
void world_inputs(std::uint64_t count, std::vector<float>& normals, std::vector<float>& views);

}  // namespace ggxnative
