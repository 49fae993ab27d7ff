// spirv_compile.hpp - the embedded shaders (kernels/*.comp, *.hlsl, with the
// device headers they include) compiled to SPIR-V 1.3 for Vulkan 1.1 by
// shaderc, with a variant's defines, and cached on disk under the key of
// the library version, the language, the defines and the whole source
// (binary_cache.hpp's store, which GGXCL_PROGRAM_CACHE moves or turns off).
// SPIR-V 1.3: glslang 12 decorates an HLSL RWStructuredBuffer with
// BufferBlock, which SPIR-V 1.4 and later refuse.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ggxcl/user_sampler.hpp"
#include "ggxcl/vulkan.hpp"

namespace ggxcl::detail {

using ShaderDefines = std::vector<std::pair<std::string, long>>;

struct CompiledShader {
    std::vector<std::uint32_t> spirv;
    bool from_disk = false;
};

// The shader of embedded file `file` in `language` (GLSL gets "#version 450"
// first; HLSL GGX_HLSL=1).  BuildError when it does not compile: the first
// error with its file and line (the embedded `#line` markers), then
// shaderc's whole log.
CompiledShader compile_shader(ShaderLanguage language, const std::string& file, const ShaderDefines& defines);

// The same with a user sampler's file after the embedded one, in the user's
// language (its defines given by the caller).  BuildError when it does not
// compile: "the user sampler does not compile: FILE:LINE: error: ...".
CompiledShader compile_user_shader(const UserSampler& user, const std::string& file, const ShaderDefines& defines);

} // namespace ggxcl::detail
