// bit_compare.hpp - what the determinism and error tests share: bit-exact
// comparison of sample sets and the message of an expected exception.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxtest {

inline bool same_bits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

inline bool same_bits(const ggxcl::SampleSet& a, const ggxcl::SampleSet& b)
{
    return a.count == b.count && same_bits(a.m, b.m) && same_bits(a.o, b.o) && same_bits(a.pdf_m, b.pdf_m) &&
           same_bits(a.pdf_o, b.pdf_o) && same_bits(a.weight, b.weight) && same_bits(a.u, b.u);
}

// what() of the Exception that `body` throws, or "(nothing thrown)".
template <typename Exception, typename Body>
std::string message_of(Body&& body)
{
    try {
        body();
    } catch (const Exception& e) {
        return e.what();
    }
    return "(nothing thrown)";
}

} // namespace ggxtest
