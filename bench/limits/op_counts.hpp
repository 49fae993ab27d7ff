// op_counts.hpp - the operations of one kernel function by class, counted in
// the LLVM IR text (.ll) that clang writes for it: the static count of the
// whole function (both sides of every branch, as a SIMD device runs them,
// masked), each vector instruction counted once per lane.  Loads, stores,
// address arithmetic, branches, phis and register moves (casts between
// integer widths, bitcasts, vector element moves) cost nothing here; an
// instruction or call this file does not know is counted as `other` and
// named, never dropped.
#pragma once

#include <array>
#include <map>
#include <string>

namespace ggxapp {

// float: float arithmetic, compares, selects, conversions, fma/mad (one op),
//        fabs, copysign, min/max, rounding;
// int: add, sub, logic, shifts, compares, selects, min/max, bit counts;
// int_mul: 32-bit (or narrower) multiplies;  int_mul_wide: 64-bit multiplies
// (Philox's 32 x 32 -> 64-bit product);  sqrt: sqrt and rsqrt;
// division: float / and reciprocals, integer division and remainder.
enum class OpClass { float_op, int_op, int_mul, int_mul_wide, sqrt, division };
inline constexpr OpClass all_op_classes[] = {OpClass::float_op, OpClass::int_op,  OpClass::int_mul,
                                             OpClass::int_mul_wide, OpClass::sqrt, OpClass::division};
inline constexpr std::size_t op_class_count = std::size(all_op_classes);
const char* op_class_name(OpClass op_class);  // "float", "int", "int mul", "int mul64", "sqrt", "div"

struct OpCounts {
    std::array<double, op_class_count> of{};  // per class, in all_op_classes order
    std::map<std::string, int> other;         // unknown opcodes and callees, with how often they appear

    double& operator[](OpClass c) { return of[static_cast<std::size_t>(c)]; }
    double operator[](OpClass c) const { return of[static_cast<std::size_t>(c)]; }
    double total() const;
    OpCounts per(double samples) const;  // every count divided by `samples` (other: unchanged)
    std::string other_text() const;      // "name x count, ..." or empty
};

// The counts of the function `kernel` (its `define ... @kernel(` line up to the closing brace) in
// `ll_text`.  Throws std::runtime_error naming the kernel when the text has no such function.
OpCounts count_kernel_ops(const std::string& ll_text, const std::string& kernel);

// The same, but throws std::runtime_error naming the unknown opcodes and callees when there are any.
OpCounts count_kernel_ops_strict(const std::string& ll_text, const std::string& kernel);

} // namespace ggxapp
