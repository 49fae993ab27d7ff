// prerequisites.hpp - whether the programs and files that `ggx` needs for
// its pages and figures, but the library does not, are on this machine, found
// as `ggx` finds them, with the reason to give skip_unless (skip.hpp) when
// they are not:
//  - three.js r111 for the 3-D views of `ggx demo`'s page (apps/html/html_page.cpp:
//    $GGX_THREE_DIR, else Debian's libjs-three);
//  - a Python with numpy and matplotlib for the PNG figures (apps/plot/plot.cpp:
//    $GGX_PYTHON, else /usr/bin/python3, else python3 on PATH);
//  - a program on PATH (binutils' nm, say).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace ggxtest {

inline const std::string three_js_reason =
    "needs three.js r111 for the demo page's 3-D views (apt-get install libjs-three, or set GGX_THREE_DIR)";
inline const std::string plotting_python_reason =
    "needs a Python with numpy and matplotlib for the figures (apt-get install python3-matplotlib, or set GGX_PYTHON)";

inline bool three_js_present()
{
    namespace fs = std::filesystem;
    const char* chosen = std::getenv("GGX_THREE_DIR");
    const fs::path from = chosen ? chosen : "/usr/share/javascript/three";
    const bool licence = chosen || fs::exists("/usr/share/doc/libjs-three/copyright");  // only Debian's is copied
    return licence && fs::exists(from / "build" / "three.min.js") &&
           fs::exists(from / "examples" / "js" / "controls" / "OrbitControls.js");
}

inline bool plotting_python_present()
{
    std::string python = "python3";
    if (const char* chosen = std::getenv("GGX_PYTHON"))
        python = chosen;
    else if (::access("/usr/bin/python3", X_OK) == 0)
        python = "/usr/bin/python3";
    const std::string probe = "'" + python + "' -c 'import numpy, matplotlib' >/dev/null 2>&1";
    const int raw = std::system(probe.c_str());
    return WIFEXITED(raw) && WEXITSTATUS(raw) == 0;
}

// Whether the shell finds `program` on PATH.
inline bool program_on_path(const std::string& program)
{
    const int raw = std::system(("command -v '" + program + "' >/dev/null 2>&1").c_str());
    return WIFEXITED(raw) && WEXITSTATUS(raw) == 0;
}

} // namespace ggxtest
