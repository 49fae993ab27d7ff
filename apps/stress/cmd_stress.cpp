// cmd_stress.cpp - `ggx stress`: the stability map.  Every method's device
// functions (as a user kernel calls them) and the host reference run the
// cases of stress_grid; the failures are counted per (alpha, theta) cell
// and kind.  Writes PREFIX.csv and a heat map per method, PREFIX-METHOD.png
// (device and host rows, a panel per failure kind), and prints the totals.
// With --eta the rough dielectric's map instead (stress_dielectric.hpp):
// a layer of cells per index, an eta column in the CSV, the totals per
// method and per index, and bounded listed as refused.  --sampler FILE.h
// adds a user sampler's device map (its own functions; the host reference
// does not know it) beside the methods'.  --html writes a page of the
// totals and the maps, naming each user sampler's file and its language.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "api_options.hpp"
#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "html_page.hpp"
#include "report_text.hpp"
#include "plot.hpp"
#include "sample_options.hpp"
#include "stress_dielectric.hpp"
#include "stress_run.hpp"

namespace ggxapp {

namespace {

struct StressCommand {
    std::string methods = "all", precision = "precise", device, out, eta, html;
    UserSamplerOptions user;
    bool no_png = false, isotropic_samplers = false;
    ApiOptions api;
};

std::vector<ggxcl::Method> parse_methods(const std::string& text)
{
    std::vector<ggxcl::Method> methods;
    for (const std::string& name : parse_name_list("--methods", text, method_names()))
        methods.push_back(ggxcl::parse_method(name));
    return methods;
}

// --eta: all (dielectric_etas) or a comma-separated list, each a float index the library accepts
// (finite, > 0, != 1); repeated values count once.
std::vector<float> parse_etas(const std::string& text)
{
    if (text == "all")
        return dielectric_etas();
    const std::string allowed = "all, or a comma-separated list of relative indices of refraction (index below "
                                "the surface over index above), each finite, > 0 and != 1 as a float, e.g. 1.5 or "
                                "0.9999,1.0001";
    if (text.empty() || text.front() == ',' || text.back() == ',' || text.find(",,") != std::string::npos)
        throw UsageError("--eta", text, allowed);
    std::vector<float> etas;
    std::stringstream items(text);
    for (std::string item; std::getline(items, item, ',');) {
        float eta = 0.0f;
        try {
            eta = parse_eta("--eta", item);
        } catch (const UsageError&) {
        }
        if (eta == 0.0f)
            throw UsageError("--eta", text, allowed);
        if (std::find(etas.begin(), etas.end(), eta) == etas.end())
            etas.push_back(eta);
    }
    return etas;
}

// The kinds a map counts, by name: the conductor's FailureKind or the dielectric's Kind.
struct KindNames {
    int count;
    const char* (*name)(int);
};

// One CSV row per cell of `map` (row-major over alpha x theta), each led by method, side and precision;
// a dielectric's map (the axes have etas) a layer of cells per eta, its rows with an eta column.
void append_rows(std::ostringstream& csv, const std::string& method, const char* side, const std::string& precision,
                 const StressAxes& axes, const StressMap& map)
{
    const std::size_t columns = axes.cos_theta.size(), layer = axes.alphas.size() * columns;
    for (std::size_t e = 0; e < std::max<std::size_t>(axes.etas.size(), 1); ++e) {
        std::ostringstream lead;
        lead << std::setprecision(9) << method << "," << side << "," << precision << ",";
        if (!axes.etas.empty())
            lead << axes.etas[e] << ",";
        for (std::size_t r = 0; r < axes.alphas.size(); ++r)
            for (std::size_t c = 0; c < columns; ++c) {
                const Counts& cell = map[e * layer + r * columns + c];
                csv << lead.str() << axes.alphas[r] << "," << axes.theta_degrees[c] << "," << cell.cases;
                for (std::uint64_t n : cell.failures)
                    csv << "," << n;
                csv << "\n";
            }
    }
}

// Adds `count` cells from `cells` on to `total`.
void add_cells(Counts& total, const Counts* cells, std::size_t count)
{
    for (std::size_t j = 0; j < count; ++j) {
        total.cases += cells[j].cases;
        total.failures.resize(cells[j].failures.size());
        for (std::size_t k = 0; k < total.failures.size(); ++k)
            total.failures[k] += cells[j].failures[k];
    }
}

void print_total(std::ostream& out, const std::string& label, const char* side, const Counts& total)
{
    out << "| " << label << " | " << side << " | " << total.cases;
    for (std::uint64_t n : total.failures)
        out << " | " << n;
    out << " |\n";
}

struct StressPlan {
    std::vector<ggxcl::Method> methods;
    std::vector<std::shared_ptr<const ggxcl::UserSampler>> users;  // their device maps after the methods
    ggxcl::Precision precision = ggxcl::Precision::precise;
    std::vector<float> etas;  // empty: the conductor's map
    ApiChoice api;
};

StressPlan plan_stress(const StressCommand& cmd)
{
    StressPlan plan;
    plan.methods = parse_methods(cmd.methods);
    plan.precision = parse_precision_option("--precision", cmd.precision);
    if (!cmd.eta.empty())
        plan.etas = parse_etas(cmd.eta);
    plan.api = cmd.api.choose(cmd.device, cmd.user.files);
    plan.users = cmd.user.load(plan.api);
    if (!plan.users.empty() && !plan.etas.empty())
        throw UsageError("--eta", cmd.eta,
                         "no --eta with --sampler: " + std::string(ggxcl::method_traits(ggxcl::Method::user).limits));
    if (cmd.isotropic_samplers && plan.users.empty())
        throw UsageError("--isotropic-samplers maps the --sampler files: give one with --sampler");
    return plan;
}

// The header of a totals table (Markdown) whose first column is `first`.
void print_table_header(std::ostream& out, const std::string& first, const KindNames& kinds)
{
    out << "| " << first << " | side | cases";
    for (int k = 0; k < kinds.count; ++k)
        out << " | " << kinds.name(k);
    out << " |\n|---|---|---|";
    for (int k = 0; k < kinds.count; ++k)
        out << "---|";
    out << "\n";
}

// The maps of one method or user sampler: the device's and the host reference's (none for a user
// sampler: the reference does not know it).
struct MethodMaps {
    std::string method;
    StressMap device, host;
};

// The maps of `method` over its cases: the dielectric's where the axes have etas.
MethodMaps maps_of(ggxcl::Backend& sampler, ggxcl::Method method, ggxcl::Precision precision, const StressAxes& axes)
{
    const std::string name(ggxcl::method_name(method));
    if (axes.etas.empty()) {
        const std::vector<StressCase> cases = stress_cases(method, axes);
        const std::vector<StressOutcome> reference = host_outcomes(method, cases);  // drawn once for both maps
        return {name, map_against(device_outcomes(sampler, method, precision, cases), reference, cases, axes),
                map_against(reference, reference, cases, axes)};
    }
    const std::vector<StressCase> cases = dielectric_cases(method, axes);
    return {name, dielectric::device_map(sampler, method, precision, cases, axes),
            dielectric::host_map(method, cases, axes)};
}

// The maps' rows in the CSV and their totals in the table, device then host.
void report(std::ostringstream& csv, std::ostream& out, const std::string& precision, const StressAxes& axes,
            const MethodMaps& maps)
{
    for (const char* side : {"device", "host"}) {
        const StressMap& map = side[0] == 'd' ? maps.device : maps.host;
        if (map.empty())
            continue;
        append_rows(csv, maps.method, side, side[0] == 'd' ? precision : "double", axes, map);
        Counts total;
        add_cells(total, map.data(), map.size());
        print_total(out, maps.method, side, total);
    }
}

// The totals per index over every method run, device and host.
void print_eta_totals(std::ostream& out, const StressAxes& axes, const KindNames& kinds,
                      const std::vector<MethodMaps>& runs)
{
    out << "\nPer index, every method together:\n\n";
    print_table_header(out, "eta", kinds);
    const std::size_t layer = axes.alphas.size() * axes.cos_theta.size();
    for (std::size_t e = 0; e < axes.etas.size(); ++e)
        for (const char* side : {"device", "host"}) {
            Counts total;
            for (const MethodMaps& run : runs)
                add_cells(total, (side[0] == 'd' ? run.device : run.host).data() + e * layer, layer);
            std::ostringstream label;
            label << std::setprecision(9) << axes.etas[e];
            print_total(out, label.str(), side, total);
        }
}

// Every method's maps (with --eta the dielectric's, the methods without a dielectric sampler listed as
// refused, then the totals per index), then the user samplers' device maps: the CSV and the totals.
void run_maps(const StressCommand& cmd, const StressPlan& plan, ggxcl::Backend& sampler, std::ostream& out)
{
    const bool per_eta = !plan.etas.empty();
    const StressAxes axes = per_eta ? dielectric_axes(plan.etas) : stress_axes();
    const KindNames kinds = per_eta ? KindNames{dielectric::kinds, dielectric::kind_name}
                                    : KindNames{failure_kinds, failure_name};
    std::ostringstream csv;
    csv << std::setprecision(9) << "method,side,precision," << (per_eta ? "eta," : "") << "alpha,theta_degrees,cases";
    for (int k = 0; k < kinds.count; ++k)
        csv << "," << kinds.name(k);
    csv << "\n";
    print_table_header(out, "method", kinds);
    std::vector<MethodMaps> runs;
    for (ggxcl::Method method : plan.methods) {
        if (per_eta && !ggxcl::method_traits(method).dielectric) {
            out << "| " << ggxcl::method_name(method) << " | refused: " << ggxcl::method_traits(method).limits
                << " |\n";
            continue;
        }
        runs.push_back(maps_of(sampler, method, plan.precision, axes));
        report(csv, out, cmd.precision, axes, runs.back());
    }
    for (const auto& user : plan.users) {  // conductors only (plan_stress)
        std::vector<StressCase> cases = stress_cases(ggxcl::Method::user, axes, cmd.isotropic_samplers);
        report(csv, out, cmd.precision, axes,
               {user->name(),
                device_stress_map(sampler, ggxcl::Method::user, plan.precision, cases, axes, true, user.get()), {}});
    }
    if (per_eta && !runs.empty())
        print_eta_totals(out, axes, kinds, runs);
    write_text_file(cmd.out + ".csv", csv.str());
}

// The page: what was run, the totals, and each chart the plot script drew.
std::string stress_markdown(const StressCommand& cmd, const StressPlan& plan, const std::string& device,
                            const std::string& totals)
{
    std::ostringstream md;
    md << "# ggx stress\n\n- Command: `" << command_line() << "`\n- Date: " << utc_now() << "\n- Device: " << device
       << ", " << cmd.precision << " mode\n";
    for (const auto& user : plan.users)
        md << "- Sampler " << user->name() << ": `" << user->path() << "`, " << user->language_name() << "\n";
    md << "\n"
       << (plan.etas.empty() ? "Every method's device functions and the double-precision reference over roughness x "
                               "view x uniforms (edge and random), counted per kind of failure. "
                             : "The rough dielectric's cases over relative index x roughness x view x uniforms, "
                               "counted per kind of failure. ")
       << "Each column counts the cases of one kind (a non-finite value, the fallback, a normal or direction off "
          "its side, a pdf that is not positive or disagrees with its recomputation); docs/STABILITY.md says what "
          "each kind means. The maps show where in roughness x view they happen.\n\n## Totals\n\n"
       << totals;
    std::vector<std::string> charts;
    for (ggxcl::Method method : plan.methods)
        if (plan.etas.empty() || ggxcl::method_traits(method).dielectric)
            charts.emplace_back(ggxcl::method_name(method));
    for (const auto& user : plan.users)
        charts.push_back(user->name());
    if (!plan.etas.empty())
        charts.emplace_back("eta");
    for (const std::string& chart : charts) {
        const std::string png = cmd.out + "-" + chart + ".png";
        if (std::filesystem::exists(png))
            md << "\n## " << chart << "\n\n![" << chart << ": where it fails](" << relative_to(png, cmd.html) << ")\n";
    }
    return md.str();
}

void run_stress(const StressCommand& cmd, const StressPlan& plan)
{
    check_writable_folder("--out", cmd.out + ".csv");
    if (!cmd.html.empty())
        check_writable_folder("--html", cmd.html);
    const std::unique_ptr<ggxcl::Backend> device = plan.api.open();
    std::ostringstream totals;
    run_maps(cmd, plan, *device, totals);
    std::cout << totals.str();
    if (!cmd.no_png)
        run_plot_script("plot_stress.py", {cmd.out + ".csv", cmd.out});
    if (!cmd.html.empty())
        write_markdown_page(cmd.html, stress_markdown(cmd, plan, device->device_label(), totals.str()));
}

} // namespace

Prepare add_stress_command(CLI::App& app)
{
    auto s = std::make_shared<StressCommand>();
    CLI::App* cmd = app.add_subcommand("stress", "Stability map: failures of every method over alpha x view x uniforms, "
                                                 "device and host reference");
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all");
    s->user.add_to(*cmd);
    cmd->add_option("--precision", s->precision, "precision mode on the device: one of " + ggxcl::precision_list());
    cmd->add_option("--device", s->device, "device index or name part (see `ggx devices`)");
    cmd->add_option("--eta", s->eta, "the rough dielectric's map instead, over these relative indices (index below "
                                     "the surface over index above; comma-separated, each > 0 and != 1), or all: "
                                     "near 1 from both sides, typical and extreme (every method with a dielectric "
                                     "sampler)");
    cmd->add_option("--out", s->out, "output prefix: PREFIX.csv and PREFIX-METHOD.png; required");
    cmd->add_flag("--no-png", s->no_png, "write the CSV only (no Python needed)");
    cmd->add_flag("--isotropic-samplers", s->isotropic_samplers,
                  "map the --sampler files on isotropic roughness alone (alpha_x = alpha_y), as an isotropic "
                  "engine meets it");
    cmd->add_option("--html", s->html, "write a web page of the totals and the maps");
    s->api.add_to(*cmd);
    return [cmd, s]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        StressPlan plan = plan_stress(*s);
        if (s->out.empty())  // what is missing, once every value given has been checked
            throw UsageError("--out is required: an output prefix such as results/stress");
        return Work{[s, plan] { run_stress(*s, plan); }, {}};
    };
}

} // namespace ggxapp
