// user_sampler.cpp - reading a user sampler's file (its includes expanded,
// #line markers naming each file), what it defines and claims, and the
// source of a program built with it.
#include "ggxcl/user_sampler.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

#include "cache_roots.hpp"
#include "ggxcl/cl/ggx_contract.h"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/method.hpp"

namespace fs = std::filesystem;

namespace ggxcl {

namespace {

// The user's files, read once each: the expanded text and the user's own text (comments out).
struct Expansion {
    std::string source, own_code;
    std::set<std::string> seen;
    bool shader = false;  // GLSL or HLSL: the lines shader_only_line() names are left out
};

// A line a shader file has for a shader of its own, which the program it joins already has:
// `#version`, `#extension GL_GOOGLE_include_directive`, `#pragma once`.
bool shader_only_line(const std::string& line)
{
    static const std::regex own(R"re(^\s*#\s*(version\b|extension\s+GL_GOOGLE_include_directive\b|pragma\s+once\b).*)re");
    return std::regex_match(line, own);
}

bool is_device_header(const std::string& name)
{
    for (const std::string& file : kernel_files())
        if (file == name)
            return true;
    return false;
}

std::string read_text(const fs::path& path, const std::string& included_from)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InvalidArgument("sampler", path.string(),
                              included_from.empty() ? "a readable file" : "a readable file (included from " +
                                                                              included_from + ")");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// `text` without its comments (string literals are not expected in a sampler).
std::string without_comments(const std::string& text)
{
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    return std::regex_replace(text, comments, " ");
}

// Appends `path` to the expansion: quoted includes of device headers by their embedded text,
// others relative to the including file, each file once.
void expand(const fs::path& path, const std::string& included_from, Expansion& out)
{
    const fs::path canonical = fs::weakly_canonical(path);
    if (!out.seen.insert(canonical.string()).second)
        return;
    static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)"\s*$)re");
    const std::string text = read_text(path, included_from);
    out.own_code += without_comments(text) + "\n";
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    out.source += "#line 1 \"" + path.string() + "\"\n";
    while (std::getline(lines, line)) {
        ++number;
        std::smatch match;
        if (!std::regex_match(line, match, include_line)) {
            out.source += (out.shader && shader_only_line(line) ? std::string() : line) + "\n";
            continue;
        }
        const std::string name = match[1];
        if (is_device_header(name))
            out.source += kernel_source(name) + "\n";
        else
            expand(path.parent_path() / name, path.string(), out);
        out.source += "#line " + std::to_string(number + 1) + " \"" + path.string() + "\"\n";
    }
}

bool defines_function(const std::string& code, const std::string& name)
{
    return std::regex_search(code, std::regex("\\b" + name + "\\s*\\("));
}

Distribution claimed_distribution(const std::string& code, const std::string& path)
{
    static const std::regex line(R"(#\s*define\s+GGX_USER_DISTRIBUTION\s+GGX_USER_(VNDF|NDF|OWN)\b)");
    std::smatch match;
    if (!std::regex_search(code, match, line))
        throw InvalidArgument("sampler", path,
                              "a file that states its distribution: #define GGX_USER_DISTRIBUTION GGX_USER_VNDF "
                              "(or GGX_USER_NDF, GGX_USER_OWN)");
    return match[1] == "VNDF" ? Distribution::vndf : match[1] == "NDF" ? Distribution::ndf : Distribution::own;
}

void check_name(const std::string& name)
{
    static const std::regex allowed(R"([A-Za-z0-9_.-]{1,40})");
    if (!std::regex_match(name, allowed))
        throw InvalidArgument("sampler name", name, "1-40 letters, digits, '_', '-' or '.'");
    for (Method method : all_methods)
        if (method_name(method) == name)
            throw InvalidArgument("sampler name", name, "a name that is not a built-in method's (" + method_list() +
                                                            ")");
}

// The first line of `log` that contains `word`; empty when none does.
std::string first_line_with(const std::string& log, const std::string& word)
{
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line))
        if (line.find(word) != std::string::npos)
            return line;
    return "";
}

// A build log's error line with its location first: PoCL's "error: FILE:L:C: message" as
// "FILE:L:C: error: message"; other lines (clang's, NVIDIA's mapped ones start so) as they are.
std::string location_first(const std::string& line)
{
    static const std::regex pocl(R"(^\s*((?:fatal )?error): (.+?:\d+:(?:\d+:)?) )");
    std::smatch match;
    if (!std::regex_search(line, match, pocl))
        return line;
    return match[2].str() + " " + match[1].str() + ": " + match.suffix().str();
}

// What follows the kernel file in a program built with a user sampler, and whence it came.
struct UserPart {
    std::string source, path;
    std::optional<ShaderLanguage> language;
};

std::mutex sources_mutex;
std::map<std::string, UserPart>& user_parts()  // by key
{
    static std::map<std::string, UserPart> parts;
    return parts;
}

} // namespace

std::optional<ShaderLanguage> shader_language_of_file(const std::string& path)
{
    const std::string extension = fs::path(path).extension().string();
    if (extension == ".glsl")
        return ShaderLanguage::glsl;
    if (extension == ".hlsl")
        return ShaderLanguage::hlsl;
    return std::nullopt;
}

std::string UserSampler::language_name() const
{
    return !language_ ? "OpenCL C" : *language_ == ShaderLanguage::hlsl ? "HLSL" : "GLSL";
}

std::shared_ptr<const UserSampler> UserSampler::load(const std::string& path, const std::string& name,
                                                     std::optional<ShaderLanguage> language)
{
    Expansion expansion;
    expansion.shader = (language ? language : shader_language_of_file(path)).has_value();
    expand(fs::path(path), "", expansion);
    std::shared_ptr<UserSampler> sampler(new UserSampler());
    sampler->language_ = language ? language : shader_language_of_file(path);
    sampler->path_ = path;
    sampler->name_ = name.empty() ? fs::path(path).stem().string() : name;
    check_name(sampler->name_);
    const std::string& code = expansion.own_code;
    sampler->samples_m_ = defines_function(code, "ggx_user_sample_m");
    if (!sampler->samples_m_ && !defines_function(code, "ggx_user_sample"))
        throw InvalidArgument("sampler", path,
                              "a file that defines ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float "
                              "u1, float u2) or ggx_vec3 ggx_user_sample_m(...) with the same arguments");
    if (!defines_function(code, "ggx_user_pdf"))
        throw InvalidArgument("sampler", path,
                              "a file that defines float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)");
    sampler->distribution_ = claimed_distribution(code, path);
    // The device checks the claim it compiles against the one read here (an #error of plain
    // words: GLSL has no string literal).
    sampler->source_ = expansion.source + "#if GGX_USER_DISTRIBUTION != " +
                       std::to_string(static_cast<int>(sampler->distribution_)) +
                       "\n#error GGX_USER_DISTRIBUTION is stated more than once or conditionally\n#endif\n";
    char key[17];
    std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(detail::fnv1a(sampler->language_name() + "\n" + sampler->source_)));
    sampler->key_ = key;
    std::lock_guard<std::mutex> lock(sources_mutex);
    user_parts()[sampler->key_] = {sampler->source_, sampler->path_, sampler->language_};
    return sampler;
}

std::string user_sampler_options(const UserSampler& sampler)
{
    return " -DGGX_USER_SAMPLER=1 -DGGX_USER_SAMPLES_M=" + std::to_string(sampler.samples_m() ? 1 : 0) +
           " -DGGX_USER_SOURCE=0x" + sampler.key() + "ull";
}

std::string program_source(const std::string& file, const std::string& options)
{
    static const std::regex marker(R"(-DGGX_USER_SOURCE=0x([0-9a-f]{16})ull)");
    std::smatch match;
    if (!std::regex_search(options, match, marker))
        return kernel_source(file);
    std::lock_guard<std::mutex> lock(sources_mutex);
    auto found = user_parts().find(match[1]);
    if (found == user_parts().end())
        throw InvalidArgument("options", match[0], "the marker of a sampler loaded in this process (UserSampler::load)");
    const UserPart& part = found->second;
    if (part.language)
        throw InvalidArgument("sampler", part.path,
                              "a user sampler in OpenCL C on an OpenCL device (this file is " +
                                  std::string(*part.language == ShaderLanguage::hlsl ? "HLSL" : "GLSL") +
                                  ": it runs on Vulkan, VulkanSampler or ggx --api vulkan)");
    return kernel_source(file) + "\n" + part.source;
}

std::string user_build_summary(const std::string& log)
{
    std::string line = first_line_with(log, "error:");  // not a warning in a file named *error*
    if (line.empty())
        line = first_line_with(log, "error");
    if (line.empty())
        return "the user sampler does not compile";
    return "the user sampler does not compile: " + location_first(line);
}

} // namespace ggxcl
