// cmd_demo.cpp - `ggx demo`: the README's main job.  For one configuration
// (alpha 0.3, view at 60 degrees by default) and every method it writes a
// sample cloud (.npy with sidecar, and .ply), a histogram with its figure,
// and one summary page, index.md, with each method's chi-square p-value and
// throughput and the figures embedded, and index.html, the same with a
// rotatable 3-D view of each method's cloud (demo_page.hpp); one line per
// method says where.
// With --eta, a rough dielectric: every method but bounded, over the whole sphere.
// --sampler FILE.h adds a user sampler (tested against its own pdf).
#include <filesystem>
#include <iostream>
#include <sstream>

#include "api_options.hpp"
#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "demo_page.hpp"
#include "html_page.hpp"
#include "histogram_job.hpp"
#include "report_text.hpp"
#include "sample_job.hpp"
#include "sample_options.hpp"

namespace ggxapp {

namespace {

struct DemoCommand {
    SampleOptions options;
    UserSamplerOptions user;  // --sampler FILE.h: added to the methods
    std::string count = "1e5", histogram_count = "1e6", cloud_points = "10000", out = "ggx-demo";
    bool no_png = false, no_html = false;
    ApiOptions api;  // --api, --shader-language
};

struct MethodResult {
    SamplerChoice method;
    HistogramResult histogram;
    ggxcl::SampleSet cloud;  // the page's points: the first of the method's cloud
};

SampleJob cloud_job(const SampleOptions& options, const SamplerChoice& method, std::uint64_t count,
                    const std::string& out)
{
    SampleJob job;
    job.params = options.params_for(method.method, method.user);
    job.theta_degrees = options.parsed_theta();
    job.phi_degrees = options.parsed_phi();
    job.range = {options.parsed_seed(), 0, count};
    job.format = format_of("--out", out);
    job.fields = job.format == Format::ply ? ply_fields({ggxcl::Field::o})
                                           : std::vector<ggxcl::Field>{ggxcl::Field::m, ggxcl::Field::o,
                                                                       ggxcl::Field::pdf_o, ggxcl::Field::weight};
    job.out = out;
    return job;
}

// The methods the demo runs: all, or for a dielectric those with a dielectric sampler (all but
// bounded), then the user samplers (conductors only).
std::vector<SamplerChoice> demo_methods(const DemoCommand& demo, const ApiChoice& api)
{
    std::vector<ggxcl::Method> methods;
    const bool dielectric = demo.options.parsed_eta() != 0.0f;
    for (ggxcl::Method method : ggxcl::all_methods)
        if (!dielectric || ggxcl::method_traits(method).dielectric)
            methods.push_back(method);
    if (dielectric && !demo.user.files.empty())
        throw UsageError("--eta", demo.options.eta,
                         "0 with --sampler: " + std::string(ggxcl::method_traits(ggxcl::Method::user).limits));
    return sampler_choices(methods, demo.user.load(api));
}

// What the histograms bin: a conductor's reflections, or a dielectric's reflections and
// refractions over the whole sphere.
std::string binned_text(const DemoCommand& demo)
{
    const float eta = demo.options.parsed_eta();
    if (eta == 0.0f)
        return "Each method's reflected directions o,";
    std::ostringstream text;
    text << "A rough dielectric, eta " << eta << " (index below the surface over index above), "
         << ggxcl::transport_name(demo.options.parsed_transport()) << " transport: each sample reflects with the "
         << "exact Fresnel F(i.m), else refracts. Each method's directions o over the whole sphere (cos theta in "
            "[-1, 1]: reflections above the surface, refractions below),";
    return text.str();
}

// The page's first lines: the configuration and what was measured how.
void write_intro(std::ostream& md, const DemoCommand& demo, const std::string& device)
{
    const bool dielectric = demo.options.parsed_eta() != 0.0f;
    md << "# ggx demo\n\nalpha " << demo.options.alpha << ", view theta " << demo.options.theta << " deg, phi "
       << demo.options.phi << " deg, seed " << demo.options.seed;
    if (dielectric)
        md << ", eta " << demo.options.parsed_eta() << ", " << ggxcl::transport_name(demo.options.parsed_transport())
           << " transport";
    md << "; device: " << device << "\n\n"
       << binned_text(demo)
       << " binned on the device over (phi, cos theta) in bins of equal solid "
          "angle, against the counts its pdf predicts (chi-square, sparse bins pooled). ";
    if (dielectric)
        md << "Samples without density (a reflection that left the view's side, a refraction that did not cross) "
              "are counted apart and tested as one more category. ";
    md << "Throughput is device sampling and binning in "
       << demo.options.precision << " mode" << (demo.options.precision == "precise" ? " (the default)" : "")
       << ", uniforms from the " << demo.options.sequence << " sequence"
       << (demo.options.sequence == "philox" ? " (the default)"
                                             : " (a net spreads its points more evenly than independent draws, so "
                                               "the chi-square statistic runs below its law and p-values near 1)")
       << ".\n\n";
}

// The page's intro and the table of every method's verdict and speed.
std::string summary_table(const DemoCommand& demo, const std::vector<MethodResult>& results, const std::string& device)
{
    std::ostringstream md;
    write_intro(md, demo, device);
    md << "| method | chi-square | dof | p-value | samples/s | files |\n|---|---|---|---|---|---|\n";
    for (const MethodResult& r : results) {
        const std::string name = r.method.name();
        md << "| " << name << " | " << readable_number(r.histogram.chi_square, 4) << " | " << r.histogram.dof << " | "
           << readable_number(r.histogram.p_value) << " | " << rate_text(r.histogram.samples_per_second, "samples/s")
           << " | " << name << ".npy, " << name << ".ply, " << name << ".hist.* |\n";
    }
    if (demo.options.parsed_eta() != 0.0f)
        for (const ggxcl::MethodTraits& t : ggxcl::method_table)
            if (!t.dielectric)
                md << "\n" << t.name << " is left out: it has no exact dielectric sampler (" << t.limits << ").\n";
    return md.str();
}

std::string summary_page(const DemoCommand& demo, const std::vector<MethodResult>& results, const std::string& device)
{
    std::ostringstream md;
    md << summary_table(demo, results, device);
    for (const MethodResult& r : results)
        if (!r.histogram.png.empty())
            md << "\n## " << r.method.name() << "\n\n![" << r.method.name()
               << " histogram](" << std::filesystem::path(r.histogram.png).filename().string() << ")\n";
    return md.str();
}

struct DemoCounts {
    std::uint64_t cloud = 0, histogram = 0, page_points = 0;
};

// Checks every option for every method; returns the counts and what will be sampled.
DemoCounts check_demo(const DemoCommand& demo, const ApiChoice& api, std::vector<Batch>& batches)
{
    DemoCounts counts{parse_count("-n", demo.count), parse_count("--histogram-n", demo.histogram_count),
                      parse_count("--page-points", demo.cloud_points)};
    if (counts.page_points > 1000000)
        throw UsageError("--page-points", demo.cloud_points, "1 .. 1e6 (each point is about 13 bytes of page)");
    counts.page_points = std::min(counts.page_points, counts.cloud);
    if (!demo.no_html)
        require_three_js();
    std::vector<ggxcl::SampleParams> params;
    for (const SamplerChoice& method : demo_methods(demo, api))
        params.push_back(demo.options.for_method(method.method).params_for(method.method, method.user));
    std::uint64_t seed = demo.options.parsed_seed();
    for (const ggxcl::SampleParams& p : params) {
        batches.push_back({p, {seed, 0, counts.cloud}});
        batches.push_back({p, {seed, 0, counts.histogram}});
    }
    return counts;
}

// Every method's files and the pages, drawn by `sampler`.
void run_demo_on(ggxcl::Backend& sampler, const ApiChoice& api, const DemoCommand& demo, DemoCounts counts)
{
    const std::string device = sampler.device_label();
    const std::uint64_t count = counts.cloud, histogram_count = counts.histogram;
    std::cout << "device: " << device << "\n";
    std::vector<MethodResult> results;
    for (const SamplerChoice& method : demo_methods(demo, api)) {
        SampleOptions options = demo.options.for_method(method.method);
        std::string base = demo.out + "/" + method.name();
        run_sample_job(sampler, cloud_job(options, method, count, base + ".npy"));
        run_sample_job(sampler, cloud_job(options, method, count, base + ".ply"));
        HistogramJob h;
        h.params = options.params_for(method.method, method.user);
        h.against = method.method;
        h.theta_degrees = options.parsed_theta();
        h.phi_degrees = options.parsed_phi();
        h.range = {options.parsed_seed(), 0, histogram_count};
        h.prefix = base + ".hist";
        h.png = !demo.no_png;
        results.push_back({method, run_histogram_job(sampler, h), {}});
        if (!demo.no_html)
            results.back().cloud = sampler.generate(h.params, {options.parsed_seed(), 0, counts.page_points},
                                                    {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_m,
                                                     ggxcl::Field::pdf_o});
        std::cout << method.name() << ": samples in " << base << ".npy and " << base << ".ply, histogram "
                  << h.prefix << (h.png ? ".png" : ".json") << " (p = " << results.back().histogram.p_value << ")\n";
    }
    write_text_file(demo.out + "/index.md", summary_page(demo, results, device));
    std::cout << "summary: " << demo.out << "/index.md\n";
    if (demo.no_html)
        return;
    std::vector<DemoPageMethod> page;
    for (MethodResult& r : results)
        page.push_back({r.method.name(), r.histogram, std::move(r.cloud)});
    const ggxcl::SampleParams first = demo.options.params_for(ggxcl::Method::caps, nullptr);
    write_demo_page(demo.out + "/index.html", summary_table(demo, results, device), page, first.view);
    std::cout << "page: " << demo.out << "/index.html (open it in a browser; three.js in " << demo.out << "/three)\n";
}

void run_demo(const DemoCommand& demo, DemoCounts counts, const ApiChoice& api)
{
    std::filesystem::create_directories(demo.out);
    check_writable_folder("--out", demo.out + "/index.md");
    run_demo_on(*api.open(), api, demo, counts);
}

} // namespace

Prepare add_demo_command(CLI::App& app)
{
    auto state = std::make_shared<DemoCommand>();
    CLI::App* cmd = app.add_subcommand("demo", "Samples, histograms and a summary page for every method");
    state->options.add_view_options(*cmd);
    cmd->add_option("-n,--count", state->count, "samples per method in the clouds");
    cmd->add_option("--histogram-n", state->histogram_count, "samples per method in the histograms");
    cmd->add_option("--page-points", state->cloud_points, "samples per method in index.html's 3-D views (at most -n)");
    cmd->add_flag("--no-png", state->no_png, "skip the figures (no Python needed)");
    cmd->add_flag("--no-html", state->no_html, "skip index.html (no three.js needed)");
    cmd->add_option("--out", state->out, "output folder");
    state->user.add_to(*cmd);
    state->api.add_to(*cmd);
    return [cmd, state]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        std::vector<Batch> batches;
        const ApiChoice api = state->api.choose(state->options.device, state->user.files);
        DemoCounts counts = check_demo(*state, api, batches);
        return Work{[state, counts, api] { run_demo(*state, counts, api); }, batches};
    };
}

} // namespace ggxapp
