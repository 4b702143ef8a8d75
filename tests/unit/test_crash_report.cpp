// The crash report (core/crash_report.hpp): a process that takes a fatal signal writes the
// signal and its stack to standard error, then still dies of that signal.
#include "core/crash_report.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace {

// Runs a child that installs the report and raises `number`; its standard error and how it
// ended.
struct Crashed {
    std::string stderrText;
    int status = 0;
};
Crashed crashWith(int number) {
    int pipeEnds[2];
    EXPECT_EQ(pipe(pipeEnds), 0);
    const pid_t child = fork();
    if (child == 0) {
        dup2(pipeEnds[1], STDERR_FILENO);
        close(pipeEnds[0]);
        rmsc::installCrashReport();
        raise(number);
        _exit(0); // not reached when the report raises the signal again
    }
    close(pipeEnds[1]);
    Crashed crashed;
    char buffer[4096];
    for (ssize_t n; (n = read(pipeEnds[0], buffer, sizeof buffer)) > 0;)
        crashed.stderrText.append(buffer, std::size_t(n));
    close(pipeEnds[0]);
    waitpid(child, &crashed.status, 0);
    return crashed;
}

} // namespace

TEST(CrashReport, AFatalSignalWritesItsStackAndStillEndsTheProcess) {
    for (const auto& [number, name] :
         {std::pair{SIGSEGV, "SIGSEGV"}, std::pair{SIGABRT, "SIGABRT"}}) {
        const Crashed crashed = crashWith(number);
        ASSERT_TRUE(WIFSIGNALED(crashed.status)) << name << ": " << crashed.stderrText;
        EXPECT_EQ(WTERMSIG(crashed.status), number) << name;
        EXPECT_NE(crashed.stderrText.find(std::string("rmsc: crashed on ") + name),
                  std::string::npos)
            << crashed.stderrText;
        // At least the handler's frame and the raise below it, each "module(+offset)[address]".
        std::size_t frames = 0;
        for (std::size_t at = 0; (at = crashed.stderrText.find(")[0x", at)) != std::string::npos;
             ++at)
            ++frames;
        EXPECT_GE(frames, 2u) << crashed.stderrText;
    }
}
