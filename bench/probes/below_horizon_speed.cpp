// below_horizon_speed.cpp - device ns per sample of the write job (m and pdf_m into device memory,
// ggxcl::benchmark::DeviceJobs) at alpha 0.3 and the view angle given (default 120 degrees: programs
// built with GGX_BELOW_HORIZON=1; below 90 the =0 ones), per method: the median of 15 profiled runs
// after a warm-up.  Built against two commits' libraries and run in turn, it times a change to the
// samplers' below-horizon forms (docs/COST-PROBES.md "Views below the horizon").
//   below_horizon_speed [THETA_DEGREES]
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>
#include <ggxcl/ggxcl.hpp>
#include <ggxcl/benchmark.hpp>
int main(int argc, char** argv)
{
    const double theta = argc > 1 ? std::stod(argv[1]) : 120.0;
    const int runs = 15;
    auto backend = ggxcl::open_backend(ggxcl::Api::opencl, "", ggxcl::ShaderLanguage::glsl);
    const std::uint64_t count = 1u << 22;
    auto jobs = ggxcl::benchmark::device_jobs(*backend, count, {});
    for (ggxcl::Method method : {ggxcl::Method::ndf, ggxcl::Method::heitz, ggxcl::Method::caps,
                                 ggxcl::Method::caps_iso, ggxcl::Method::bounded}) {
        ggxcl::SampleParams p;
        p.method = method;
        p.alpha_x = p.alpha_y = 0.3f;
        p.view = ggxcl::view_from_angles(theta, 35.0);
        jobs->run(ggxcl::benchmark::Job::write, p, 1);  // builds the program
        std::vector<double> ns;
        for (int r = 0; r < runs; ++r)
            ns.push_back(jobs->run(ggxcl::benchmark::Job::write, p, 1 + r).device_ns / double(count));
        std::sort(ns.begin(), ns.end());
        std::printf("%s %.4f\n", std::string(ggxcl::method_name(method)).c_str(), ns[ns.size() / 2]);
    }
}
