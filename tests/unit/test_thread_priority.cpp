// Background threads lower their own priority (core/thread_priority.hpp): the calling thread's
// nice value goes up, the other threads' does not, and threads it starts inherit it.
#include "core/thread_priority.hpp"

#include <gtest/gtest.h>

#include <thread>

#if defined(__linux__)
#include <cerrno>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

int thisThreadsNice() {
    errno = 0;
    return getpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)));
}

} // namespace

TEST(ThreadPriority, OnlyTheCallingThreadAndItsChildrenAreLowered) {
    const int before = thisThreadsNice();
    int lowered = 0, child = 0;
    std::thread worker([&] {
        rmsc::lowerThisThreadsPriority();
        lowered = thisThreadsNice();
        std::thread inner([&] { child = thisThreadsNice(); });
        inner.join();
    });
    worker.join();
    EXPECT_EQ(lowered, std::min(before + 10, 19));
    EXPECT_EQ(child, lowered);
    EXPECT_EQ(thisThreadsNice(), before); // this thread keeps its priority
}
#endif
