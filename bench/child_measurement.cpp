#include "child_measurement.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ivis::bench {

Measurement measureInChild(const std::string& label, const std::function<double()>& work)
{
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        ::close(fds[0]);
        double result[2] = {0.0, 0.0};
        try {
            const auto start = std::chrono::steady_clock::now();
            result[1] = work();
            result[0] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "inversevis-bench: %s failed: %s\n", label.c_str(), e.what());
            ::_exit(1);
        }
        const ssize_t written = ::write(fds[1], result, sizeof result);
        ::_exit(written == sizeof result ? 0 : 1);
    }
    ::close(fds[1]);
    double result[2] = {0.0, 0.0};
    const ssize_t got = ::read(fds[0], result, sizeof result);
    ::close(fds[0]);
    int status = 0;
    struct rusage usage {};
    ::wait4(pid, &status, 0, &usage);
    if (got != sizeof result || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(label + " failed in the measuring child");
    return {result[0], usage.ru_maxrss * 1024LL, result[1]};
}

}  // namespace ivis::bench
