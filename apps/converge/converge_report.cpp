// converge_report.cpp - the CSVs and the Markdown report of `ggx converge`.
#include "converge_report.hpp"

#include "report_text.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace ggxapp {

namespace {

std::string number(double value, const char* format = "%.6g")
{
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string curve_name(const ConvergeCurve& c)
{
    return std::string(c.method.name()) + " | " + std::string(ggxcl::sequence_name(c.sequence));
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// The curves of one method and sequence for one integrand, in configuration order.
std::vector<const ConvergeCurve*> curves_of(const std::vector<ConvergeCurve>& curves, const SamplerChoice& method,
                                            ggxcl::Sequence sequence, Integrand integrand)
{
    std::vector<const ConvergeCurve*> found;
    for (const ConvergeCurve& c : curves)
        if (c.method == method && c.sequence == sequence && c.integrand == integrand)
            found.push_back(&c);
    return found;
}

// One table per integrand: a row per method and sequence, a column per
// configuration, each cell the slope (or, with `rmse`, the RMSE at the
// largest count relative to the exact value), and the median slope.
void table(std::ostringstream& md, const ConvergePlan& plan, const std::vector<ConvergeCurve>& curves,
           Integrand integrand, bool rmse)
{
    md << "| method | sequence |" << (rmse ? "" : " median |");
    for (const ConvergeConfig& c : plan.configs)
        md << " a " << number(c.alpha, "%g") << ", " << number(c.theta, "%g") << " deg |";
    md << "\n|---|---|" << (rmse ? "" : "---|");
    for (std::size_t k = 0; k < plan.configs.size(); ++k)
        md << "---|";
    md << "\n";
    for (const SamplerChoice& method : plan.methods)
        for (ggxcl::Sequence sequence : plan.sequences) {
            std::vector<const ConvergeCurve*> row = curves_of(curves, method, sequence, integrand);
            std::vector<double> slopes;
            for (const ConvergeCurve* c : row)
                slopes.push_back(c->slope);
            md << "| " << curve_name(*row.front()) << " |" << (rmse ? "" : " " + number(median(slopes), "%.2f") + " |");
            for (const ConvergeCurve* c : row)
                md << " " << (rmse ? readable_number(c->rmse.back() / c->reference) : number(c->slope, "%.2f")) << " |";
            md << "\n";
        }
    md << "\n";
}

} // namespace

std::string converge_csv(const std::vector<ConvergeCurve>& curves, int randomizations)
{
    std::ostringstream csv;
    csv << "method,sequence,integrand,alpha,theta_degrees,n,rmse,mean,reference,randomizations,slope\n";
    for (const ConvergeCurve& c : curves)
        for (std::size_t k = 0; k < c.counts.size(); ++k)
            csv << c.method.name() << "," << ggxcl::sequence_name(c.sequence) << ","
                << integrand_name(c.integrand) << "," << number(c.config.alpha) << "," << number(c.config.theta) << ","
                << c.counts[k] << "," << number(c.rmse[k], "%.9g") << "," << number(c.mean[k], "%.12g") << ","
                << number(c.reference, "%.12g") << "," << randomizations << "," << number(c.slope, "%.4f") << "\n";
    return csv.str();
}

std::string speeds_csv(const std::vector<ConvergeSpeed>& speeds)
{
    std::ostringstream csv;
    csv << "method,sequence,ns_per_sample\n";
    for (const ConvergeSpeed& s : speeds)
        csv << s.method.name() << "," << ggxcl::sequence_name(s.sequence) << ","
            << number(s.ns_per_sample, "%.4f") << "\n";
    return csv.str();
}

std::string converge_markdown(const ConvergeReportInfo& info, const ConvergePlan& plan,
                              const std::vector<ConvergeCurve>& curves, const std::vector<ConvergeSpeed>& speeds)
{
    std::ostringstream md;
    md << "# Convergence of the estimators (generated)\n\n"
       << "`" << info.command << "`  \n" << info.date << ", " << info.device << "; " << info.randomizations
       << " independent streams per point, sample counts 2^" << plan.min_exponent << " .. 2^" << plan.max_exponent
       << ", " << ggxcl::precision_name(plan.precision) << " mode. Slopes are least-squares fits of log RMSE "
       << "against log N over every count (plain Monte Carlo: -0.5).\n\n";
    for (Integrand integrand : plan.integrands) {
        md << "## " << integrand_name(integrand) << "\n\n";
        if (!info.charts_prefix.empty())
            md << "![" << integrand_name(integrand) << "](" << info.charts_prefix << "-" << integrand_name(integrand)
               << ".png)\n\n";
        md << "Slope of log RMSE against log N:\n\n";
        table(md, plan, curves, integrand, false);
        md << "RMSE at N = 2^" << plan.max_exponent << ", relative to the exact value:\n\n";
        table(md, plan, curves, integrand, true);
    }
    if (!speeds.empty()) {
        md << "## Speed (the fused estimator, ns per sample, median)\n\n| method | sequence | ns |\n|---|---|---|\n";
        for (const ConvergeSpeed& s : speeds)
            md << "| " << s.method.name() << " | " << ggxcl::sequence_name(s.sequence) << " | "
               << number(s.ns_per_sample, "%.3f") << " |\n";
        md << "\n";
        if (!info.charts_prefix.empty())
            md << "![RMSE at equal time](" << info.charts_prefix << "-time.png)\n\n";
    }
    return md.str();
}

} // namespace ggxapp
