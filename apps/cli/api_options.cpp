// api_options.cpp - --api, --shader-language and the vulkan: prefix.
#include "api_options.hpp"

#include "library_errors.hpp"

namespace ggxapp {

namespace {
const std::string vulkan_prefix = "vulkan:";
}

std::optional<ggxcl::ShaderLanguage> ApiChoice::sampler_language(const std::string& file) const
{
    if (api != ggxcl::Api::vulkan)
        return std::nullopt;
    return ggxcl::shader_language_of_file(file).value_or(language);
}

std::unique_ptr<ggxcl::Backend> ApiChoice::open() const
{
    return ggxcl::open_backend(api, selector, language);
}

std::vector<std::string> ApiChoice::arguments() const
{
    std::vector<std::string> words = {"--api", ggxcl::api_name(api)};
    if (api == ggxcl::Api::vulkan)
        words.insert(words.end(), {"--shader-language", ggxcl::shader_language_name(language)});
    if (!selector.empty())
        words.insert(words.end(), {"--device", selector});
    return words;
}

const ApiChoice& choice_for_file(const std::string& file, const std::vector<ApiChoice>& choices)
{
    const bool shader = ggxcl::shader_language_of_file(file).has_value();
    for (const ApiChoice& choice : choices)
        if ((choice.api == ggxcl::Api::vulkan) == shader)
            return choice;
    return choices.front();
}

void ApiOptions::add_to(CLI::App& cmd)
{
    api_option = cmd.add_option("--api", api,
                                "opencl or vulkan: the API the samplers run on (vulkan: compute shaders compiled "
                                "from the same headers; a --device of vulkan:NAME implies it)");
    language_option = cmd.add_option("--shader-language", shader_language,
                                     "glsl or hlsl: the language of the Vulkan shaders (with --api vulkan)");
}

namespace {

// The first of `files` whose extension names a shading language, or none.
const std::string* first_shader_file(const std::vector<std::string>& files)
{
    for (const std::string& file : files)
        if (ggxcl::shader_language_of_file(file))
            return &file;
    return nullptr;
}

} // namespace

ApiChoice ApiOptions::choose(const std::string& device, const std::vector<std::string>& sampler_files) const
{
    ApiChoice choice;
    const ggxcl::Api named = parsed_option("--api", api, "opencl or vulkan", ggxcl::parse_api);
    const bool api_given = api_option && api_option->count() > 0;
    const bool language_given = language_option && language_option->count() > 0;
    const bool prefixed = device.rfind(vulkan_prefix, 0) == 0;
    if (prefixed && api_given && named == ggxcl::Api::opencl)
        throw UsageError("--device", device, "an OpenCL device with --api opencl (`ggx devices` lists both)");
    const std::string* shader_file = first_shader_file(sampler_files);
    if (shader_file && api_given && named == ggxcl::Api::opencl)
        throw UsageError("--api", api, "vulkan with a GLSL or HLSL --sampler (" + *shader_file +
                                           " runs on Vulkan; OpenCL runs OpenCL C)");
    const bool vulkan = named == ggxcl::Api::vulkan || prefixed || shader_file;
    choice.api = vulkan ? ggxcl::Api::vulkan : ggxcl::Api::opencl;
    choice.selector = prefixed ? device.substr(vulkan_prefix.size()) : device;
    choice.language = parsed_option("--shader-language", shader_language, "glsl or hlsl", ggxcl::parse_shader_language);
    if (!vulkan && language_given)
        throw UsageError("--shader-language", shader_language, "nothing without --api vulkan (OpenCL runs OpenCL C)");
    for (const std::string& file : sampler_files) {
        const std::optional<ggxcl::ShaderLanguage> own = ggxcl::shader_language_of_file(file);
        if (own && language_given && *own != choice.language)
            throw UsageError("--shader-language", shader_language,
                             std::string(ggxcl::shader_language_name(*own)) + ", the language of --sampler " + file +
                                 " (its extension says; a file of another extension is read in --shader-language)");
    }
    if (shader_file && !language_given)
        choice.language = *ggxcl::shader_language_of_file(*shader_file);
    return choice;
}

std::vector<ApiChoice> ApiOptions::choose_list(const std::string& device,
                                               const std::vector<std::string>& sampler_files) const
{
    const std::vector<std::string> names = parse_name_list("--api", api, {"opencl", "vulkan"});
    if (names.size() == 1)
        return {choose(device, sampler_files)};
    ApiOptions each = *this;
    const bool prefixed = device.rfind(vulkan_prefix, 0) == 0;
    each.api = "opencl";
    each.language_option = nullptr;  // --shader-language is Vulkan's
    ApiChoice opencl = each.choose(prefixed ? "" : device);
    each.api = "vulkan";
    each.language_option = language_option;
    ApiChoice vulkan = each.choose(prefixed ? device : "", sampler_files);
    return {opencl, vulkan};
}

} // namespace ggxapp
