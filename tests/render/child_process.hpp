// SPDX-License-Identifier: MIT
// Running a piece of a test in a child process: what would block, crash or
// take memory the test means to measure happens there, and only its answer
// comes back.
#pragma once
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <string>

namespace ds::render::test {

// What fn returns, run in a child that an alarm ends after 10 s (a FIFO
// that would block for ever), or "killed by signal N".
inline std::string in_child(const std::function<std::string()>& fn) {
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        alarm(10);
        const std::string out = fn();
        (void)!write(fds[1], out.data(), out.size());
        _exit(0);
    }
    close(fds[1]);
    std::string out;
    char buf[512];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
    return out;
}

// The peak resident memory, in kB, that a child process gains running fn
// (its peak reset first): what fn allocated at most, give or take a page.
inline long child_peak_kb(void (*fn)()) {
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    const pid_t pid = fork();
    if (pid == 0) {
        std::ofstream("/proc/self/clear_refs") << "5";  // resets VmHWM to the current RSS
        auto kb = [](const char* key) {
            std::ifstream in("/proc/self/status");
            std::string line;
            while (std::getline(in, line))
                if (line.rfind(key, 0) == 0) return std::stol(line.substr(std::strlen(key)));
            return -1L;
        };
        const long before = kb("VmRSS:");
        fn();
        const long grew = kb("VmHWM:") - before;
        (void)!write(fds[1], &grew, sizeof grew);
        _exit(0);
    }
    close(fds[1]);
    long grew = -1;
    (void)!read(fds[0], &grew, sizeof grew);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return grew;
}

}  // namespace ds::render::test
