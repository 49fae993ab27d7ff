// list_programs.cpp - the programs ggxcl builds, for the offline GPU compilers
// (compile_programs.py): writes the embedded kernel sources, as the runtime
// builds them, into a folder, and prints one JSON object a line per program:
// its file, kind, method, precision and options on a GPU.
//   list_programs SOURCE_DIR covering   every option value and pair of values (program_variants.hpp)
//   list_programs SOURCE_DIR jobs       the programs of `ggx bench`'s jobs, per method (docs/DEVICES.md)
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "device_contract.hpp"
#include "device_quirks.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "program_variants.hpp"
#include "stress_request.hpp"

namespace {

using ggxcl::detail::ProgramKind;
using ggxcl::detail::ProgramVariant;

// A GPU's single-precision config as AMD's and NVIDIA's drivers report it: fma, and correctly rounded
// division and sqrt (so precise mode builds with -cl-fp32-correctly-rounded-divide-sqrt).
constexpr cl_device_fp_config gpu_fp_config =
    CL_FP_DENORM | CL_FP_INF_NAN | CL_FP_ROUND_TO_NEAREST | CL_FP_FMA | CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT;

nlohmann::json program(const std::string& name, const std::string& file, const std::string& kind,
                       ggxcl::Method method, ggxcl::Precision precision, const std::string& defines)
{
    return {{"name", name},
            {"file", file},
            {"kind", kind},
            {"method", std::string(ggxcl::method_name(method))},
            {"precision", std::string(ggxcl::precision_name(precision))},
            {"options", defines + ggxcl::detail::precision_options_for(precision, gpu_fp_config)}};
}

nlohmann::json program_of(const std::string& name, const ProgramVariant& v)
{
    return program(name, ggxcl::detail::program_file(v.kind), ggxcl::detail::program_kind_name(v.kind), v.method,
                   v.precision, ggxcl::detail::variant_defines(v));
}

void write_sources(const std::filesystem::path& folder)
{
    std::filesystem::create_directories(folder);
    for (const std::string& file : ggxcl::kernel_files())
        std::ofstream(folder / file, std::ios::binary) << ggxcl::kernel_source(file);
}

void print_covering()
{
    int k = 0;
    for (const ProgramVariant& v : ggxcl::detail::covering_variants())
        std::cout << program_of(std::string(ggxcl::detail::program_kind_name(v.kind)) + "-" + std::to_string(k++), v)
                         .dump()
                  << "\n";
    // The stability map's programs: every method in both modes, with and without the guards, such
    // that each method and each mode meets both settings of the guards.
    for (std::size_t i = 0; i < ggxcl::all_methods.size(); ++i)
        for (std::size_t p = 0; p < ggxcl::all_precisions.size(); ++p) {
            const ggxcl::Method m = ggxcl::all_methods[i];
            const bool guards = (i + p) % 2 == 0;
            std::cout << program("stress-" + std::to_string(k++), "ggx_stress.cl", "stress", m,
                                 ggxcl::all_precisions[p], ggxcl::detail::stress_defines({m, ggxcl::all_precisions[p], guards}))
                             .dump()
                      << "\n";
        }
}

// `ggx bench`'s jobs (apps/bench/bench_speed.cpp) at its defaults: alpha 0.3, a view 60 degrees from
// the normal, precise mode; write stores m and pdf_m with guards, the furnace runs unguarded, world
// space reads a view and a normal per sample, pdf is the bulk program's pdf kernel.
void print_jobs()
{
    for (ggxcl::Method m : ggxcl::all_methods) {
        ggxcl::SampleParams params;
        params.method = m;
        params.alpha_x = params.alpha_y = 0.3f;
        params.view = ggxcl::view_from_angles(60.0, 0.0);
        const unsigned write = (1u << GGX_FIELD_M) | (1u << GGX_FIELD_PDF_M);
        const std::string name(ggxcl::method_name(m));
        ProgramVariant v = ggxcl::detail::variant_of(ProgramKind::bulk, params, write);
        std::cout << program_of(name + ":write", v).dump() << "\n";
        ggxcl::SampleParams unguarded = params;  // furnace() draws without the guards first
        unguarded.guards = false;
        v = ggxcl::detail::variant_of(ProgramKind::furnace, unguarded, 1u << GGX_FIELD_WEIGHT);
        std::cout << program_of(name + ":furnace", v).dump() << "\n";
        params.world_space = true;
        v = ggxcl::detail::variant_of(ProgramKind::bulk, params, 1u << GGX_FIELD_O);
        v.per_sample_view = v.per_sample_normal = true;  // the bench's buffers of views and normals
        v.normal_is_z = false;
        std::cout << program_of(name + ":world", v).dump() << "\n";
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::string what = argc == 3 ? argv[2] : "";
    if (what != "covering" && what != "jobs") {
        std::cerr << "usage: list_programs SOURCE_DIR covering|jobs\n";
        return 2;
    }
    write_sources(argv[1]);
    if (what == "covering")
        print_covering();
    else
        print_jobs();
    return 0;
}
