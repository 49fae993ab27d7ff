// backend_factories.hpp - how open_backend (backend.cpp) reaches each back end
// without including it: each back end defines its own opener (opencl/,
// vulkan/; a build without Vulkan: vulkan_absent.cpp).
#pragma once

#include <memory>
#include <string>

#include "ggxcl/backend.hpp"

namespace ggxcl::detail {

std::unique_ptr<Backend> open_opencl_backend(const std::string& selector);
std::unique_ptr<Backend> open_vulkan_backend(const std::string& selector, ShaderLanguage language);

} // namespace ggxcl::detail
