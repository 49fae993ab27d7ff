// plot.cpp - runs the embedded matplotlib scripts.
#include "plot.hpp"

#include <cstdlib>
#include <filesystem>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.hpp"
#include "embedded_sources.hpp"

extern char** environ;

namespace ggxapp {

namespace {

const char* script_text(const std::string& name)
{
    for (std::size_t k = 0; k < detail::embedded_source_count; ++k)
        if (name == detail::embedded_sources[k].name)
            return detail::embedded_sources[k].text;
    throw std::logic_error("no embedded script " + name);
}

std::string python_interpreter()
{
    if (const char* chosen = std::getenv("GGX_PYTHON"))
        return chosen;
    return ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
}

} // namespace

void run_plot_script(const std::string& script, const std::vector<std::string>& args)
{
    std::filesystem::path temp = std::filesystem::temp_directory_path() /
                                 ("ggx-" + std::to_string(::getpid()) + "-" + script);
    write_text_file(temp.string(), script_text(script));
    std::string python = python_interpreter();
    std::vector<std::string> words = {python, temp.string()};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    argv.push_back(nullptr);
    pid_t pid;
    int status = -1;
    bool started = ::posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) == 0;
    if (started)
        ::waitpid(pid, &status, 0);
    std::filesystem::remove(temp);
    if (!started || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("the PNG was not drawn: " + python +
                                 " with numpy and matplotlib is needed (Debian: apt-get install python3-matplotlib)");
}

} // namespace ggxapp
