// generate_dump.cpp - test_python's window on the C++ library: draws one
// range with Sampler::generate (every field) and writes the SampleSet's
// planar floats as they are, field after field (m, o, pdf_m, pdf_o,
// weight, u), to a raw file, so pytest can compare the module's arrays
// with what the C++ API returns, not only with `ggx sample`'s files.
// Usage: generate_dump METHOD ALPHA_X ALPHA_Y THETA PHI SEED FIRST COUNT OUT
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include <ggxcl/ggxcl.hpp>

int main(int argc, char** argv)
{
    if (argc != 10) {
        std::fprintf(stderr, "usage: generate_dump METHOD ALPHA_X ALPHA_Y THETA PHI SEED FIRST COUNT OUT\n");
        return 2;
    }
    try {
        ggxcl::SampleParams p;
        p.method = ggxcl::parse_method(argv[1]);
        p.alpha_x = std::stof(argv[2]);
        p.alpha_y = std::stof(argv[3]);
        p.view = ggxcl::view_from_angles(std::stod(argv[4]), std::stod(argv[5]));
        const ggxcl::SampleRange range{std::stoull(argv[6]), std::stoull(argv[7]), std::stoull(argv[8])};
        ggxcl::Sampler sampler;
        const ggxcl::SampleSet set = sampler.generate(p, range, ggxcl::FieldSet::all());
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
