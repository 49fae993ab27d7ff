// child_process.cpp - posix_spawn with both output pipes drained by poll(), so that a child
// writing much on either never blocks on the other, until the child's time limit if it has one.
#include "child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>

extern char** environ;

namespace ggxapp {

namespace {

// A file descriptor closed when it goes out of scope.
struct Descriptor {
    int fd = -1;
    Descriptor() = default;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() { reset(); }
    void reset()
    {
        if (fd >= 0)
            ::close(fd);
        fd = -1;
    }
};

struct Pipe {
    Descriptor read, write;
};

void open_pipe(Pipe& p, const std::string& command)
{
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw std::system_error(errno, std::generic_category(), "cannot start `" + command + "`: pipe");
    p.read.fd = fds[0];
    p.write.fd = fds[1];
}

using Clock = std::chrono::steady_clock;

// Milliseconds poll() may wait before `deadline` (-1: no deadline).
int poll_timeout_ms(const Clock::time_point* deadline)
{
    if (!deadline)
        return -1;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - Clock::now()).count();
    return int(std::max<long long>(0, std::min<long long>(left, 1 << 30)));
}

// Reads both pipes to their ends; throws ChildTimedOut when `deadline` passes first.
void drain(Pipe& out, Pipe& err, ChildOutput& result, const Clock::time_point* deadline, const std::string& why)
{
    char buffer[65536];
    pollfd fds[2] = {{out.read.fd, POLLIN, 0}, {err.read.fd, POLLIN, 0}};
    std::string* texts[2] = {&result.out, &result.err};
    int open = 2;
    while (open > 0) {
        const int ready = ::poll(fds, 2, poll_timeout_ms(deadline));
        if (ready < 0) {
            if (errno == EINTR)
                continue;
            throw std::system_error(errno, std::generic_category(), "poll");
        }
        if (ready == 0)
            throw ChildTimedOut(why);
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || fds[k].revents == 0)
                continue;
            ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
            if (n > 0) {
                texts[k]->append(buffer, std::size_t(n));
            } else if (n == 0 || errno != EINTR) {
                fds[k].fd = -1;  // end of file (or an error: nothing more will come)
                --open;
            }
        }
    }
}

// This process's environment with each "NAME=value" of `settings` in place of NAME's.
std::vector<std::string> environment_with(const std::vector<std::string>& settings)
{
    std::vector<std::string> env = settings;
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('=') + 1);
        if (std::none_of(settings.begin(), settings.end(), [&](const std::string& s) { return s.rfind(name, 0) == 0; }))
            env.push_back(entry);
    }
    return env;
}

} // namespace

ChildOutput run_child(const std::string& program, const std::vector<std::string>& arguments, double limit_s,
                      const std::vector<std::string>& settings)
{
    const std::string command = command_text(program, arguments);
    Pipe out, err;
    open_pipe(out, command);
    open_pipe(err, command);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<std::string> environment = environment_with(settings);
    std::vector<char*> envp;
    for (std::string& e : environment)
        envp.push_back(e.data());
    envp.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out.write.fd, 1);
    posix_spawn_file_actions_adddup2(&actions, err.write.fd, 2);
    pid_t pid = 0;
    int spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::system_error(spawned, std::generic_category(), "cannot start `" + command + "`");
    out.write.reset();  // the child holds the write ends now
    err.write.reset();

    ChildOutput result;
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit_s));
    try {
        drain(out, err, result, limit_s > 0 ? &deadline : nullptr,
              "`" + command + "` ran past its limit of " + std::to_string(int(std::ceil(limit_s))) +
                  " s and was stopped");
    } catch (...) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        throw;
    }
    while (::waitpid(pid, &result.status, 0) < 0)
        if (errno != EINTR)
            throw std::system_error(errno, std::generic_category(), "waiting for `" + command + "`");
    return result;
}

bool exited_ok(int status)
{
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string describe_exit(int status)
{
    if (WIFEXITED(status))
        return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status))
        return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    return "ended with wait status " + std::to_string(status);
}

std::string command_text(const std::string& program, const std::vector<std::string>& arguments)
{
    std::string text = program;
    for (const std::string& a : arguments)
        text += " " + a;
    return text;
}

} // namespace ggxapp
