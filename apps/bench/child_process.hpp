// child_process.hpp - running a helper program as a child process: posix_spawn (no shell, the
// environment inherited, stdin from /dev/null), its stdout and stderr captured whole, and its
// exit status put into words for error messages.
#pragma once

#include <string>
#include <vector>

namespace ggxapp {

struct ChildOutput {
    int status = 0;       // as waitpid() reports it
    std::string out, err; // everything the child wrote on stdout and stderr
};

// Runs `program` (a path) with `arguments` and waits for it.  Throws std::system_error when it
// cannot be started (the message names the command).
ChildOutput run_child(const std::string& program, const std::vector<std::string>& arguments);

bool exited_ok(int status);               // exited normally with status 0
std::string describe_exit(int status);    // "exited with status 2", "was killed by signal 4 (Illegal instruction)"
std::string command_text(const std::string& program, const std::vector<std::string>& arguments);

} // namespace ggxapp
