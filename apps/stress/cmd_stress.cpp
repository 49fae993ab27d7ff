// cmd_stress.cpp - `ggx stress`: the stability map.  Every method's device
// functions (as a user kernel calls them) and the host reference run the
// cases of stress_grid; the failures are counted per (alpha, theta) cell
// and kind.  Writes PREFIX.csv and a heat map per method, PREFIX-METHOD.png
// (device and host rows, a panel per failure kind), and prints the totals.
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "plot.hpp"
#include "sample_options.hpp"
#include "stress_run.hpp"

namespace ggxapp {

namespace {

struct StressCommand {
    std::string methods = "all", precision = "precise", device, out;
    bool no_png = false;
};

std::vector<ggxcl::Method> parse_methods(const std::string& text)
{
    std::vector<ggxcl::Method> methods;
    for (const std::string& name : parse_name_list("--methods", text, method_names()))
        methods.push_back(ggxcl::parse_method(name));
    return methods;
}

void append_rows(std::ostringstream& csv, const std::string& method, const char* side, const std::string& precision,
                 const StressAxes& axes, const StressMap& map)
{
    for (std::size_t r = 0; r < axes.alphas.size(); ++r)
        for (std::size_t c = 0; c < axes.cos_theta.size(); ++c) {
            const CellCounts& cell = map[r * axes.cos_theta.size() + c];
            csv << method << "," << side << "," << precision << "," << axes.alphas[r] << "," << axes.theta_degrees[c]
                << "," << cell.cases;
            for (std::uint64_t n : cell.failures)
                csv << "," << n;
            csv << "\n";
        }
}

void print_totals(const std::string& method, const char* side, const StressMap& map)
{
    CellCounts total;
    for (const CellCounts& cell : map) {
        total.cases += cell.cases;
        for (int k = 0; k < failure_kinds; ++k)
            total.failures[k] += cell.failures[k];
    }
    std::cout << "| " << method << " | " << side << " | " << total.cases;
    for (std::uint64_t n : total.failures)
        std::cout << " | " << n;
    std::cout << " |\n";
}

struct StressPlan {
    std::vector<ggxcl::Method> methods;
    ggxcl::Precision precision = ggxcl::Precision::precise;
};

StressPlan plan_stress(const StressCommand& cmd)
{
    StressPlan plan{parse_methods(cmd.methods)};
    try {
        plan.precision = ggxcl::parse_precision(cmd.precision);
    } catch (const ggxcl::InvalidArgument&) {
        throw UsageError("--precision", cmd.precision, "one of " + ggxcl::precision_list());
    }
    return plan;
}

// The CSV's header line and the totals table's header (Markdown).
void write_headers(std::ostringstream& csv)
{
    csv << std::setprecision(9) << "method,side,precision,alpha,theta_degrees,cases";
    for (int k = 0; k < failure_kinds; ++k)
        csv << "," << failure_name(k);
    csv << "\n";
    std::cout << "| method | side | cases";
    for (int k = 0; k < failure_kinds; ++k)
        std::cout << " | " << failure_name(k);
    std::cout << " |\n|---|---|---|";
    for (int k = 0; k < failure_kinds; ++k)
        std::cout << "---|";
    std::cout << "\n";
}

void run_stress(const StressCommand& cmd, const StressPlan& plan)
{
    check_writable_folder("--out", cmd.out + ".csv");
    ggxcl::Sampler sampler(cmd.device);
    StressAxes axes = stress_axes();
    std::ostringstream csv;
    write_headers(csv);
    for (ggxcl::Method method : plan.methods) {
        std::string name(ggxcl::method_name(method));
        std::vector<StressCase> cases = stress_cases(method, axes);
        StressMap device = device_stress_map(sampler, method, plan.precision, cases, axes);
        StressMap host = host_stress_map(method, cases, axes);
        append_rows(csv, name, "device", cmd.precision, axes, device);
        append_rows(csv, name, "host", "double", axes, host);
        print_totals(name, "device", device);
        print_totals(name, "host", host);
    }
    write_text_file(cmd.out + ".csv", csv.str());
    if (!cmd.no_png)
        run_plot_script("plot_stress.py", {cmd.out + ".csv", cmd.out});
}

} // namespace

Prepare add_stress_command(CLI::App& app)
{
    auto s = std::make_shared<StressCommand>();
    CLI::App* cmd = app.add_subcommand("stress", "Stability map: failures of every method over alpha x view x uniforms, "
                                                 "device and host reference");
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all")->capture_default_str();
    cmd->add_option("--precision", s->precision, "precision mode on the device: one of " + ggxcl::precision_list())
        ->capture_default_str();
    cmd->add_option("--device", s->device, "device index or name part (see `ggx devices`)");
    cmd->add_option("--out", s->out, "output prefix: PREFIX.csv and PREFIX-METHOD.png")->required();
    cmd->add_flag("--no-png", s->no_png, "write the CSV only (no Python needed)");
    return [cmd, s]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        StressPlan plan = plan_stress(*s);
        return Work{[s, plan] { run_stress(*s, plan); }, {}};
    };
}

} // namespace ggxapp
