// child_process.hpp - running a helper program as a child process: posix_spawn (no shell, the
// environment inherited, stdin from /dev/null), its stdout and stderr captured whole, and its
// exit status put into words for error messages; a child that runs past its
// time limit is killed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace ggxapp {

struct ChildOutput {
    int status = 0;       // as waitpid() reports it
    std::string out, err; // everything the child wrote on stdout and stderr
};

// The child ran past its time limit and was killed; what() names the command and the limit.
struct ChildTimedOut : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Runs `program` (a path) with `arguments` and waits for it, at most `limit_s` seconds when that is
// > 0 (then kills it with SIGKILL and throws ChildTimedOut).  Its environment is this process's with
// each "NAME=value" of `settings` in place of NAME's.  Throws std::system_error when it cannot be
// started (the message names the command).
ChildOutput run_child(const std::string& program, const std::vector<std::string>& arguments, double limit_s = 0,
                      const std::vector<std::string>& settings = {});

bool exited_ok(int status);               // exited normally with status 0
std::string describe_exit(int status);    // "exited with status 2", "was killed by signal 4 (Illegal instruction)"
std::string command_text(const std::string& program, const std::vector<std::string>& arguments);

} // namespace ggxapp
