// plot.hpp - PNG figures drawn by matplotlib: the app carries its plotting
// script embedded, writes it to a temporary file and runs Python on it.
// The interpreter is $GGX_PYTHON, else /usr/bin/python3, else python3.
#pragma once

#include <string>
#include <vector>

namespace ggxapp {

// Runs the embedded script `script` with `args`; throws std::runtime_error
// saying what to install when Python or matplotlib is missing.
void run_plot_script(const std::string& script, const std::vector<std::string>& args);

} // namespace ggxapp
