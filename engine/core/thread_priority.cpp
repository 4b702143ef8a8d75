// The background threads' priority (see core/thread_priority.hpp).
#include "core/thread_priority.hpp"

#if defined(__linux__)
#include <cerrno>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace rmsc {

void lowerThisThreadsPriority() {
#if defined(__linux__)
    // setpriority(2) with a thread id sets that thread's nice value alone (Linux); failing is
    // harmless (the thread keeps its priority).
    const id_t thread = id_t(syscall(SYS_gettid));
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, thread);
    if (errno == 0) (void)setpriority(PRIO_PROCESS, thread, nice + 10 > 19 ? 19 : nice + 10);
#endif
}

} // namespace rmsc
