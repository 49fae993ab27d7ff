// test_paths.hpp - the paths CMake compiles into a test (GGX_BINARY,
// GGX_USER_SAMPLERS_DIR, ... as string macros), each overridable at run time
// by the environment variable of the same name, so that test programs carried
// to another machine find their copies there:
//   GGX_BINARY=/bundle/bin/ggx ./test_cli
// A function is defined for each macro the test was built with.
#pragma once

#include <cstdlib>
#include <string>

namespace ggxtest {

// $variable when set and not empty, else the value compiled in.
inline std::string path_from_env(const char* variable, const char* compiled_default)
{
    const char* chosen = std::getenv(variable);
    return chosen && *chosen ? chosen : compiled_default;
}

#ifdef GGX_BINARY
inline std::string ggx_binary() { return path_from_env("GGX_BINARY", GGX_BINARY); }
#endif
#ifdef GGX_LIMITS_BINARY
inline std::string limits_binary() { return path_from_env("GGX_LIMITS_BINARY", GGX_LIMITS_BINARY); }
#endif
#ifdef GGX_CHECK_TARGETS
inline std::string check_targets_script() { return path_from_env("GGX_CHECK_TARGETS", GGX_CHECK_TARGETS); }
#endif
#ifdef GGX_USER_SAMPLERS_DIR
inline std::string user_samplers_dir() { return path_from_env("GGX_USER_SAMPLERS_DIR", GGX_USER_SAMPLERS_DIR); }
// tests/user_samplers/NAME (NAME may name a subfolder: "shaders/caps_copy.glsl").
inline std::string user_sampler_file(const std::string& name) { return user_samplers_dir() + "/" + name; }
#endif
#ifdef GGX_KERNEL_DIR
inline std::string kernel_dir() { return path_from_env("GGX_KERNEL_DIR", GGX_KERNEL_DIR); }
#endif
#ifdef GGX_VULKAN_SHADER_DIR
inline std::string vulkan_shader_dir() { return path_from_env("GGX_VULKAN_SHADER_DIR", GGX_VULKAN_SHADER_DIR); }
#endif
#ifdef GGX_CUDA_DIR
inline std::string cuda_dir() { return path_from_env("GGX_CUDA_DIR", GGX_CUDA_DIR); }
#endif
#ifdef GGX_EXAMPLES_DIR
inline std::string examples_dir() { return path_from_env("GGX_EXAMPLES_DIR", GGX_EXAMPLES_DIR); }
#endif
#ifdef GGX_GXX
inline std::string gxx() { return path_from_env("GGX_GXX", GGX_GXX); }
#endif
#ifdef GGX_CLANG
inline std::string clang() { return path_from_env("GGX_CLANG", GGX_CLANG); }
#endif
#ifdef GGX_GLSLANG_VALIDATOR
inline std::string glslang_validator() { return path_from_env("GGX_GLSLANG_VALIDATOR", GGX_GLSLANG_VALIDATOR); }
#endif
#ifdef GGX_CLANGXX
inline std::string clangxx() { return path_from_env("GGX_CLANGXX", GGX_CLANGXX); }
#endif
#ifdef GGX_NVCC
inline std::string nvcc() { return path_from_env("GGX_NVCC", GGX_NVCC); }
#endif
#ifdef OCLGRIND_DRIVER
inline std::string oclgrind_driver() { return path_from_env("OCLGRIND_DRIVER", OCLGRIND_DRIVER); }
#endif
#ifdef OCLGRIND_PROBE
inline std::string oclgrind_probe() { return path_from_env("OCLGRIND_PROBE", OCLGRIND_PROBE); }
#endif

} // namespace ggxtest
