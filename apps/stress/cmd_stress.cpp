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

// One CSV row per cell of `cells` (row-major over alpha x theta), each led by `lead`.
template <class Cell>
void append_cells(std::ostringstream& csv, const std::string& lead, const StressAxes& axes, const Cell* cells)
{
    for (std::size_t r = 0; r < axes.alphas.size(); ++r)
        for (std::size_t c = 0; c < axes.cos_theta.size(); ++c) {
            const Cell& cell = cells[r * axes.cos_theta.size() + c];
            csv << lead << axes.alphas[r] << "," << axes.theta_degrees[c] << "," << cell.cases;
            for (std::uint64_t n : cell.failures)
                csv << "," << n;
            csv << "\n";
        }
}

void append_rows(std::ostringstream& csv, const std::string& method, const char* side, const std::string& precision,
                 const StressAxes& axes, const StressMap& map)
{
    append_cells(csv, method + "," + side + "," + precision + ",", axes, map.data());
}

void append_dielectric_rows(std::ostringstream& csv, const std::string& method, const char* side,
                            const std::string& precision, const StressAxes& axes, const dielectric::Map& map)
{
    const std::size_t layer = axes.alphas.size() * axes.cos_theta.size();
    for (std::size_t e = 0; e < axes.etas.size(); ++e) {
        std::ostringstream lead;
        lead << std::setprecision(9) << method << "," << side << "," << precision << "," << axes.etas[e] << ",";
        append_cells(csv, lead.str(), axes, map.data() + e * layer);
    }
}

template <class Cell>
void add_cells(Cell& total, const Cell* cells, std::size_t count)
{
    for (std::size_t j = 0; j < count; ++j) {
        total.cases += cells[j].cases;
        total.failures.resize(cells[j].failures.size());
        for (std::size_t k = 0; k < total.failures.size(); ++k)
            total.failures[k] += cells[j].failures[k];
    }
}

template <class Cell>
void print_total(std::ostream& out, const std::string& label, const char* side, const Cell& total)
{
    out << "| " << label << " | " << side << " | " << total.cases;
    for (std::uint64_t n : total.failures)
        out << " | " << n;
    out << " |\n";
}

void print_totals(std::ostream& out, const std::string& method, const char* side, const StressMap& map)
{
    CellCounts total;
    add_cells(total, map.data(), map.size());
    print_total(out, method, side, total);
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
    try {
        plan.precision = ggxcl::parse_precision(cmd.precision);
    } catch (const ggxcl::InvalidArgument&) {
        throw UsageError("--precision", cmd.precision, "one of " + ggxcl::precision_list());
    }
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
void print_table_header(std::ostream& out, const std::string& first, int kinds, const char* (*name)(int))
{
    out << "| " << first << " | side | cases";
    for (int k = 0; k < kinds; ++k)
        out << " | " << name(k);
    out << " |\n|---|---|---|";
    for (int k = 0; k < kinds; ++k)
        out << "---|";
    out << "\n";
}

// The CSV's header line and the totals table's header (Markdown).
void write_headers(std::ostringstream& csv, std::ostream& out)
{
    csv << std::setprecision(9) << "method,side,precision,alpha,theta_degrees,cases";
    for (int k = 0; k < failure_kinds; ++k)
        csv << "," << failure_name(k);
    csv << "\n";
    print_table_header(out, "method", failure_kinds, failure_name);
}

void run_conductor_stress(const StressCommand& cmd, const StressPlan& plan, ggxcl::Backend& sampler, std::ostream& out)
{
    StressAxes axes = stress_axes();
    std::ostringstream csv;
    write_headers(csv, out);
    for (ggxcl::Method method : plan.methods) {
        std::string name(ggxcl::method_name(method));
        std::vector<StressCase> cases = stress_cases(method, axes);
        StressMap device = device_stress_map(sampler, method, plan.precision, cases, axes);
        StressMap host = host_stress_map(method, cases, axes);
        append_rows(csv, name, "device", cmd.precision, axes, device);
        append_rows(csv, name, "host", "double", axes, host);
        print_totals(out, name, "device", device);
        print_totals(out, name, "host", host);
    }
    for (const auto& user : plan.users) {  // the device alone: the reference does not know them
        std::vector<StressCase> cases = stress_cases(ggxcl::Method::user, axes, cmd.isotropic_samplers);
        StressMap device =
            device_stress_map(sampler, ggxcl::Method::user, plan.precision, cases, axes, true, user.get());
        append_rows(csv, user->name(), "device", cmd.precision, axes, device);
        print_totals(out, user->name(), "device", device);
    }
    write_text_file(cmd.out + ".csv", csv.str());
}

// The dielectric's maps of one method, device and host.
struct DielectricMaps {
    std::string method;
    dielectric::Map device, host;
};

// The totals per index over every method run, device and host.
void print_eta_totals(std::ostream& out, const StressAxes& axes, const std::vector<DielectricMaps>& runs)
{
    out << "\nPer index, every method together:\n\n";
    print_table_header(out, "eta", dielectric::kinds, dielectric::kind_name);
    const std::size_t layer = axes.alphas.size() * axes.cos_theta.size();
    for (std::size_t e = 0; e < axes.etas.size(); ++e)
        for (const char* side : {"device", "host"}) {
            dielectric::Counts total;
            for (const DielectricMaps& run : runs)
                add_cells(total, (side[0] == 'd' ? run.device : run.host).data() + e * layer, layer);
            std::ostringstream label;
            label << std::setprecision(9) << axes.etas[e];
            print_total(out, label.str(), side, total);
        }
}

void run_dielectric_stress(const StressCommand& cmd, const StressPlan& plan, ggxcl::Backend& sampler, std::ostream& out)
{
    StressAxes axes = dielectric_axes(plan.etas);
    std::ostringstream csv;
    csv << std::setprecision(9) << "method,side,precision,eta,alpha,theta_degrees,cases";
    for (int k = 0; k < dielectric::kinds; ++k)
        csv << "," << dielectric::kind_name(k);
    csv << "\n";
    print_table_header(out, "method", dielectric::kinds, dielectric::kind_name);
    std::vector<DielectricMaps> runs;
    for (ggxcl::Method method : plan.methods) {
        std::string name(ggxcl::method_name(method));
        if (!ggxcl::method_traits(method).dielectric) {
            out << "| " << name << " | refused: " << ggxcl::method_traits(method).limits << " |\n";
            continue;
        }
        std::vector<StressCase> cases = dielectric_cases(method, axes);
        DielectricMaps run{name, dielectric::device_map(sampler, method, plan.precision, cases, axes),
                           dielectric::host_map(method, cases, axes)};
        append_dielectric_rows(csv, name, "device", cmd.precision, axes, run.device);
        append_dielectric_rows(csv, name, "host", "double", axes, run.host);
        for (const char* side : {"device", "host"}) {
            dielectric::Counts total;
            const dielectric::Map& map = side[0] == 'd' ? run.device : run.host;
            add_cells(total, map.data(), map.size());
            print_total(out, name, side, total);
        }
        runs.push_back(std::move(run));
    }
    if (!runs.empty())
        print_eta_totals(out, axes, runs);
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
    if (plan.etas.empty())
        run_conductor_stress(cmd, plan, *device, totals);
    else
        run_dielectric_stress(cmd, plan, *device, totals);
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
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all")->capture_default_str();
    s->user.add_to(*cmd);
    cmd->add_option("--precision", s->precision, "precision mode on the device: one of " + ggxcl::precision_list())
        ->capture_default_str();
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
