// generate_dump.cpp - test_python's window on the C++ library: draws one
// range with Backend::generate (every field; OpenCL's Sampler, or with API
// vulkan a VulkanSampler in LANGUAGE) and writes the SampleSet's planar
// floats as they are, field after field (m, o, pdf_m, pdf_o, weight, u), to
// a raw file, so pytest can compare the module's arrays with what the C++
// API returns, not only with `ggx sample`'s files.
// Usage: generate_dump METHOD ALPHA_X ALPHA_Y THETA PHI SEED FIRST COUNT OUT [API [LANGUAGE]]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <memory>
#include <string>

#include <ggxcl/ggxcl.hpp>

int main(int argc, char** argv)
{
    if (argc < 10 || argc > 12) {
        std::fprintf(stderr, "usage: generate_dump METHOD ALPHA_X ALPHA_Y THETA PHI SEED FIRST COUNT OUT [API [LANGUAGE]]\n");
        return 2;
    }
    try {
        ggxcl::SampleParams p;
        p.method = ggxcl::parse_method(argv[1]);
        p.alpha_x = std::stof(argv[2]);
        p.alpha_y = std::stof(argv[3]);
        p.view = ggxcl::view_from_angles(std::stod(argv[4]), std::stod(argv[5]));
        const ggxcl::SampleRange range{std::stoull(argv[6]), std::stoull(argv[7]), std::stoull(argv[8])};
        const ggxcl::Api api = argc > 10 ? ggxcl::parse_api(argv[10]) : ggxcl::Api::opencl;
        const ggxcl::ShaderLanguage language =
            argc > 11 ? ggxcl::parse_shader_language(argv[11]) : ggxcl::ShaderLanguage::glsl;
        const std::unique_ptr<ggxcl::Backend> backend = ggxcl::open_backend(api, "", language);
        const ggxcl::SampleSet set = backend->generate(p, range, ggxcl::FieldSet::all());
        std::ofstream out(argv[9], std::ios::binary);
        for (ggxcl::Field f : ggxcl::all_fields) {
            const std::vector<float>& planes = set.column_source(f);
            out.write(reinterpret_cast<const char*>(planes.data()), std::streamsize(planes.size() * sizeof(float)));
        }
        return out.good() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "generate_dump: %s\n", e.what());
        return 1;
    }
}
