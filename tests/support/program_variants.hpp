// program_variants.hpp - the program variants the runtime can build, enumerated
// from the same options it writes (lib/src/core/program_variant.hpp), without a
// device: the list the offline GPU compilers build in tests/gpu_compilers.
// Test support (library ggx_program_variants), not part of libggxcl.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "program_variant.hpp"

namespace ggxcl::detail {

// One option of a program: how many values it has, and how value k is read and set in a variant.
struct ProgramOption {
    std::string name;  // "method", "precision", "write_mask.pdf_m", "GGX_WORLD_SPACE", ...
    int value_count;
    std::function<int(const ProgramVariant&)> get;
    std::function<void(ProgramVariant&, int)> set;
};

// Every option of the programs: the method, precision and sequence lists, one bit per field of the
// write mask, each GGX_PROGRAM_FLAGS line and the histogram's bins and binned direction.
std::vector<ProgramOption> program_options();

// Reachable variants (variant_is_reachable) of every program kind such that every value of every
// option appears, and every pair of values of two options appears together wherever some reachable
// variant of that kind has the pair: a pairwise covering set, made greedily with a fixed seed (the
// same list on every run).
std::vector<ProgramVariant> covering_variants();

} // namespace ggxcl::detail
