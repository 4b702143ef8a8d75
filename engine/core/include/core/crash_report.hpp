// What a crash leaves behind: on a fatal signal (a segmentation fault, an abort, a bus error,
// an illegal instruction, a floating-point trap) the process writes the signal and the stack of
// the thread that took it to standard error, then dies of that signal as it would have (the
// same exit status, and a core file where the system keeps them). A crash seen once, on
// someone else's machine or in a CI log, then says where it happened.
#pragma once

namespace rmsc {

// Installs the handlers for the calling process (once, at the start of main). The stack lines
// are "module(+offset)[address]": `addr2line -f -C -e rmsc OFFSET` names the function and line
// of a build with symbols.
void installCrashReport();

} // namespace rmsc
