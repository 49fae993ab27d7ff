// converge_report.hpp - what `ggx converge` writes: the CSV of every curve
// point, the CSV of the speeds, and the Markdown report (the slopes per
// method, sequence and integrand, over the configurations and each one, the
// RMSE at the largest count, the speeds and the charts).
#pragma once

#include <string>
#include <vector>

#include "converge_run.hpp"

namespace ggxapp {

// method,sequence,integrand,alpha,theta_degrees,n,rmse,mean,reference,randomizations,slope
std::string converge_csv(const std::vector<ConvergeCurve>& curves, int randomizations);
// method,sequence,ns_per_sample
std::string speeds_csv(const std::vector<ConvergeSpeed>& speeds);

struct ConvergeReportInfo {
    std::string command, date, device;
    std::string charts_prefix;  // as linked from the report; empty: no charts
    int randomizations = 0;
};
std::string converge_markdown(const ConvergeReportInfo& info, const ConvergePlan& plan,
                              const std::vector<ConvergeCurve>& curves, const std::vector<ConvergeSpeed>& speeds);

} // namespace ggxapp
