// The fatal-signal handler (see crash_report.hpp). A handler may call only async-signal-safe
// functions (POSIX, signal-safety(7)): write(2) and glibc's backtrace_symbols_fd, which writes
// without allocating; backtrace itself loads libgcc's unwinder on its first call, so it is
// called once when the handler is installed, never for the first time inside it.
#include "core/crash_report.hpp"

#include <execinfo.h>
#include <signal.h>
#include <unistd.h>

#include <cstring>

namespace rmsc {
namespace {

struct FatalSignal {
    int number;
    const char* text;
};
constexpr FatalSignal kFatalSignals[] = {
    {SIGSEGV, "SIGSEGV (segmentation fault)"},
    {SIGABRT, "SIGABRT (abort)"},
    {SIGBUS, "SIGBUS (bus error)"},
    {SIGILL, "SIGILL (illegal instruction)"},
    {SIGFPE, "SIGFPE (arithmetic trap)"},
};

void writeText(const char* text) {
    const ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

void onFatalSignal(int number) {
    const char* name = "a fatal signal";
    for (const FatalSignal& s : kFatalSignals)
        if (s.number == number) name = s.text;
    writeText("\nrmsc: crashed on ");
    writeText(name);
    writeText(". The stack of the thread that took it (module(+offset)[address]):\n");
    void* frames[64];
    backtrace_symbols_fd(frames, backtrace(frames, 64), STDERR_FILENO);
    // The handler was reset to the default one as it ran (SA_RESETHAND): the signal, raised
    // again, ends the process as it would have ended without this report.
    raise(number);
}

// A stack of its own for the handler: a stack overflow leaves none to run it on.
alignas(16) char alternateStack[64 * 1024];

} // namespace

void installCrashReport() {
    void* warm[1];
    (void)backtrace(warm, 1); // (see the top of the file)
    stack_t stack{};
    stack.ss_sp = alternateStack;
    stack.ss_size = sizeof alternateStack;
    sigaltstack(&stack, nullptr);
    struct sigaction action {};
    action.sa_handler = onFatalSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_ONSTACK;
    for (const FatalSignal& s : kFatalSignals)
        sigaction(s.number, &action, nullptr);
}

} // namespace rmsc
