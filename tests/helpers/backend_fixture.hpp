// backend_fixture.hpp - the back end a suite written once for both APIs runs
// on: GGX_TEST_API=opencl (the default: the device fixture's Sampler) or
// vulkan (a VulkanSampler in GGX_TEST_SHADER_LANGUAGE, glsl by default).
// CTest runs such a suite twice, the Vulkan instance under the validation
// layer and labelled `vulkan` (tests/CMakeLists.txt: ggx_backend_test).
#pragma once

#include <ggxcl/ggxcl.hpp>

namespace ggxtest {

// The suite's back end, opened once; null after recording a skip
// (skip.hpp) where Vulkan is asked for and this build or machine has none.
ggxcl::Backend* test_backend();

} // namespace ggxtest
