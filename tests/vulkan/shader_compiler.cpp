// shader_compiler.cpp - shaderc with an includer over a list of folders.
#include "shader_compiler.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <shaderc/shaderc.hpp>

namespace ggxvk {

namespace {

// Resolves #include "name" against the including file's folder, then `dirs`.
class FolderIncluder : public shaderc::CompileOptions::IncluderInterface {
public:
    explicit FolderIncluder(std::vector<std::string> dirs) : dirs_(std::move(dirs)) {}

    shaderc_include_result* GetInclude(const char* requested, shaderc_include_type, const char* requesting,
                                       size_t) override
    {
        auto* file = new IncludedFile;
        std::vector<std::filesystem::path> candidates{std::filesystem::path(requesting).parent_path() / requested};
        for (const std::string& dir : dirs_)
            candidates.push_back(std::filesystem::path(dir) / requested);
        for (const std::filesystem::path& path : candidates) {
            if (std::filesystem::is_regular_file(path)) {
                file->name = path.string();
                file->text = read_text_file(file->name);
                break;
            }
        }
        if (file->name.empty())  // shaderc reports an empty name with the text as the error
            file->text = std::string("cannot find ") + requested;
        file->result = {file->name.c_str(), file->name.size(), file->text.c_str(), file->text.size(), file};
        return &file->result;
    }

    void ReleaseInclude(shaderc_include_result* result) override
    {
        delete static_cast<IncludedFile*>(result->user_data);
    }

private:
    struct IncludedFile {
        std::string name, text;
        shaderc_include_result result{};
    };
    std::vector<std::string> dirs_;
};

} // namespace

std::string read_text_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::uint32_t> compile_compute_shader(const ShaderSource& source,
                                                  const std::vector<std::string>& include_dirs)
{
    shaderc::CompileOptions options;
    options.SetSourceLanguage(source.language == ShaderLanguage::hlsl ? shaderc_source_language_hlsl
                                                                      : shaderc_source_language_glsl);
    options.SetTargetEnvironment(shaderc_target_env_vulkan, shaderc_env_version_vulkan_1_1);
    options.SetTargetSpirv(shaderc_spirv_version_1_3);
    options.SetIncluder(std::make_unique<FolderIncluder>(include_dirs));
    if (source.language == ShaderLanguage::hlsl)
        options.AddMacroDefinition("GGX_HLSL", "1");
    for (const auto& [name, value] : source.defines)
        options.AddMacroDefinition(name, value);
    shaderc::Compiler compiler;
    shaderc::SpvCompilationResult result =
        compiler.CompileGlslToSpv(source.text, shaderc_compute_shader, source.name.c_str(), "main", options);
    if (result.GetCompilationStatus() != shaderc_compilation_status_success)
        throw std::runtime_error(source.name + " (" + language_name(source.language) + "): " + result.GetErrorMessage());
    return {result.cbegin(), result.cend()};
}

} // namespace ggxvk
