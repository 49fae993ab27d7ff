// user_sampler_source.hpp - what the program cache says when a user
// sampler's program does not build.
#pragma once

#include <string>

namespace ggxcl::detail {

// The first line of a build log with an error (with the #line markers of a user sampler's
// source it starts with the user's file and line), for the first line of the BuildError's log.
std::string user_build_summary(const std::string& log);

} // namespace ggxcl::detail
