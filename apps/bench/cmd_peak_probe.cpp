// cmd_peak_probe.cpp - `ggx peak-probe` (hidden from --help): the device's compute peaks
// (bench_peak.hpp) measured in a process of their own and printed for `ggx bench`, which runs it as
// a child with a time limit.
#include <iostream>

#include "bench_peak.hpp"
#include "commands.hpp"

namespace ggxapp {

Prepare add_peak_probe_command(CLI::App& app)
{
    auto device = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("peak-probe", "The device's compute peaks, for `ggx bench`");
    cmd->group("");  // an internal command: not listed
    cmd->add_option("--device", *device, "device index or name part (see `ggx devices`)");
    return [cmd, device]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        return Work{[device] {
                        ggxcl::Sampler sampler(*device);
                        std::cout << peak_rates_text(measure_peaks(sampler)) << std::flush;
                    },
                    {}};
    };
}

} // namespace ggxapp
