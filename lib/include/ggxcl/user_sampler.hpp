// user_sampler.hpp - a GGX sampler of the user's own, in one file of OpenCL C
// (the language of the device headers; run by Sampler) or of GLSL or HLSL
// (run by VulkanSampler), run by every front end of the library in place of a
// built-in method: SampleParams{Method::user, ...} with
// SampleParams::user_sampler set.  The file defines the functions of
// kernels/ggx_user_sampler.h (ggx_user_sample or ggx_user_sample_m, and
// ggx_user_pdf) and states the distribution it claims with
// `#define GGX_USER_DISTRIBUTION GGX_USER_VNDF` (or _NDF, _OWN).
// docs/USER-SAMPLERS.md tells the whole contract.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ggxcl/method.hpp"
#include "ggxcl/shader_language.hpp"

namespace ggxcl {

class UserSampler {
public:
    // Reads the sampler in `path` and the files it includes with #include "..." (the device
    // headers by their names, others relative to the including file), each once.  `name` names
    // it in reports (default: the file's stem); it must be 1-40 letters, digits, '_', '-' or '.'
    // and no built-in method's name.  Throws InvalidArgument (parameter "sampler") naming the
    // file when it cannot be read, defines no sample function or no ggx_user_pdf, or states no
    // GGX_USER_DISTRIBUTION; (parameter "sampler name") for a bad name.  A file that does not
    // compile throws BuildError when a program is first built from it, its message starting
    // with the file and line of the first error.  `language`: the file is GLSL or HLSL, for
    // VulkanSampler; none: from its extension (.glsl, .hlsl; any other is OpenCL C, for Sampler).
    // A shader file's `#version`, `#extension GL_GOOGLE_include_directive` and `#pragma once`
    // lines are left out (the shader it joins has its own), their lines kept blank.
    static std::shared_ptr<const UserSampler> load(const std::string& path, const std::string& name = "",
                                                   std::optional<ShaderLanguage> language = std::nullopt);

    const std::string& name() const { return name_; }
    const std::string& path() const { return path_; }
    Distribution distribution() const { return distribution_; }
    // Whether the file defines ggx_user_sample_m (the library completes the sample) rather
    // than ggx_user_sample.
    bool samples_m() const { return samples_m_; }
    // The file's shading language; none for OpenCL C.
    std::optional<ShaderLanguage> shader_language() const { return language_; }
    // "OpenCL C", "GLSL" or "HLSL".
    std::string language_name() const;
    // The file with its includes expanded, framed by #line markers naming each file.
    const std::string& source() const { return source_; }
    // 16 hex digits of a hash of source(): programs built from it are cached under it, so an
    // edited file (or an edited file it includes) builds anew.
    const std::string& key() const { return key_; }

private:
    UserSampler() = default;
    std::string name_, path_, source_, key_;
    Distribution distribution_ = Distribution::vndf;
    bool samples_m_ = false;
    std::optional<ShaderLanguage> language_;
};

// The shading language of a sampler file named `path`: GLSL for .glsl, HLSL for .hlsl, none
// (OpenCL C) for any other extension.
std::optional<ShaderLanguage> shader_language_of_file(const std::string& path);

// The build options that select `sampler` in a library program (kernels/ggx_*.cl built with
// -DGGX_METHOD=GGX_METHOD_USER), its key among them:
// " -DGGX_USER_SAMPLER=1 -DGGX_USER_SAMPLES_M=0|1 -DGGX_USER_SOURCE=0x<key>ull".
std::string user_sampler_options(const UserSampler& sampler);

// The source a library program is built from: kernel_source(file) (kernel_sources.hpp), followed
// by the user sampler whose key `options` carry (one loaded in this process, in OpenCL C;
// InvalidArgument otherwise, naming the file of a GLSL or HLSL sampler).  A program's source is a function of its file and options, so the program caches
// (in memory, on disk) keep user programs like the others, and an edited file builds anew.
std::string program_source(const std::string& file, const std::string& options);

// "the user sampler does not compile: " and the first line of a build log with an error, its
// location first (the library has mapped the log's locations to the user's files, whatever the
// compiler printed), so that it starts with the user's file and line: the summary that leads the
// BuildError of a user sampler's program.
std::string user_build_summary(const std::string& log);

} // namespace ggxcl
