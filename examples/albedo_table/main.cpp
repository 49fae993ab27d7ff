// main.cpp - albedo_table: the directional albedo E(mu, alpha) of GGX
// (height-correlated Smith G2, Fresnel 1) on a 32 x 32 grid, the table a
// renderer precomputes for energy compensation, estimated on an OpenCL
// device with each ggxcl sampling method and checked against a double
// precision quadrature.  This program owns its context, queue and buffers;
// ggxcl samples into them and its own kernels include ggxcl's device headers.
//
//   albedo_table [--out DIR] [--samples N] [--seed S]
//
// Writes DIR/albedo_<method>.npy (float32, shape (32, 32): rows mu, columns
// alpha, both at the centres of 32 steps of (0, 1]) and DIR/albedo_<method>.png
// (8 pixels per cell, black 0 to white 1), and albedo_quadrature.{npy,png}.
// Exit status 1 when a cell misses its tolerance (table_check.hpp), 2 on bad
// usage.  The device is GGXCL_DEVICE's, else the first one.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <ggxcl/ggxcl.hpp>

#include "albedo_grid.hpp"
#include "device_albedo.hpp"
#include "npy_file.hpp"
#include "png_file.hpp"
#include "quadrature.hpp"
#include "table_check.hpp"

namespace {

struct Options {
    std::string out = "albedo-tables";
    std::uint32_t samples = 1u << 14;  // per cell: standard errors below 4e-3
    std::uint64_t seed = 2024;
};

Options parse(int argc, char** argv)
{
    Options options;
    for (int k = 1; k < argc; ++k) {
        const std::string flag = argv[k];
        if (k + 1 >= argc || (flag != "--out" && flag != "--samples" && flag != "--seed"))
            throw std::invalid_argument("usage: albedo_table [--out DIR] [--samples N] [--seed S]");
        const std::string value = argv[++k];
        if (flag == "--out")
            options.out = value;
        else if (flag == "--samples")
            options.samples = static_cast<std::uint32_t>(std::stoul(value));
        else
            options.seed = std::stoull(value);
    }
    if (options.samples < albedo::DeviceAlbedo::block || options.samples % albedo::DeviceAlbedo::block != 0 ||
        options.samples > (1u << 24))
        throw std::invalid_argument("--samples: a multiple of 64 from 64 to 2^24");
    return options;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_table(const std::string& dir, const std::string& name, const std::vector<float>& table)
{
    albedo::write_npy(dir + "/albedo_" + name + ".npy", table, albedo::table_size, albedo::table_size);
    albedo::write_png(dir + "/albedo_" + name + ".png", table, albedo::table_size, albedo::table_size, 8);
}

std::vector<double> quadrature_table()
{
    std::vector<double> table;
    for (const albedo::Cell& cell : albedo::table_cells())
        table.push_back(albedo::albedo_quadrature(cell.view_x, cell.view_z, cell.alpha));
    return table;
}

// Reports cells beyond their tolerance on stderr; true when there are none.
bool passes(const std::string& what, const albedo::CheckResult& check)
{
    if (check.failures > 0)
        std::fprintf(stderr, "albedo_table: %s: %d cells beyond %.0f standard errors + %.0e; worst %s\n",
                     what.c_str(), check.failures, albedo::z_limit, albedo::float_allowance, check.worst.c_str());
    return check.failures == 0;
}

// One method: device sums, the check, the files and a line of report; true when it passes.
bool run_method(albedo::DeviceAlbedo& device, ggxcl::Method method, const Options& options,
                const std::vector<double>& quadrature)
{
    const auto start = std::chrono::steady_clock::now();
    const albedo::MethodSums sums = device.run(method, options.seed);
    const auto table = albedo::estimates(sums.runtime, options.samples);
    const albedo::CheckResult check = albedo::check_table(table, quadrature);
    const std::string name(ggxcl::method_name(method));
    write_table(options.out, name, albedo::means_of(table));
    std::printf("%-9s max |E - quadrature| %.2e  max z %.2f  in-kernel sampler: %s  %.2f s\n", name.c_str(),
                check.max_abs_error, check.max_z, sums.same_bits ? "same bits" : "other rounding",
                seconds_since(start));
    bool passed = passes(name, check);
    if (!sums.same_bits)  // then the in-kernel table is a second estimate to check
        passed = passes(name + " (in-kernel sampler)",
                        albedo::check_table(albedo::estimates(sums.in_kernel, options.samples), quadrature)) &&
                 passed;
    return passed;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    try {
        options = parse(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "albedo_table: %s\n", e.what());
        return 2;
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        std::filesystem::create_directories(options.out);
        const std::vector<double> quadrature = quadrature_table();
        write_table(options.out, "quadrature", std::vector<float>(quadrature.begin(), quadrature.end()));
        std::printf("quadrature of %d cells: %.2f s\n", albedo::cell_count, seconds_since(start));

        // Our own context and queue on the device GGXCL_DEVICE names (else the first).
        const cl::Device device = ggxcl::select_device().device;
        const cl::Context context(device);
        albedo::DeviceAlbedo albedo_on_device(context, device, options.samples);
        std::printf("device %s, %u samples per cell, seed %llu\n", device.getInfo<CL_DEVICE_NAME>().c_str(),
                    options.samples, static_cast<unsigned long long>(options.seed));
        bool passed = true;
        for (ggxcl::Method method : ggxcl::all_methods)
            passed = run_method(albedo_on_device, method, options, quadrature) && passed;
        std::printf("%s: tables in %s, %.2f s\n", passed ? "passed" : "FAILED", options.out.c_str(),
                    seconds_since(start));
        return passed ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "albedo_table: %s\n", e.what());
        return 1;
    }
}
