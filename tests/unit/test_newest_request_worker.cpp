// The viewer's background worker (editor/newest_request_worker.hpp): a request that arrives
// while another is worked on replaces the one waiting, so only the newest is worked on next,
// and take() gives the newest finished result once.
#include "editor/newest_request_worker.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <mutex>
#include <vector>

using rmsc::editor::NewestRequestWorker;

namespace {

// A worker whose request 1 waits, once started, until open() is called; it records what it
// worked on and gives request * 10.
struct GatedWorker {
    std::promise<void> gate;
    std::shared_future<void> opened = gate.get_future().share();
    std::promise<void> firstStarted;
    std::mutex mutex;
    std::vector<int> worked;
    NewestRequestWorker<int, int> worker{[this](int& request) {
        if (request == 1) {
            firstStarted.set_value();
            opened.wait();
        }
        std::lock_guard lock(mutex);
        worked.push_back(request);
        return request * 10;
    }};

    void waitForTheFirst() { firstStarted.get_future().wait(); }
    void open() { gate.set_value(); }
    std::vector<int> workedOn() {
        std::lock_guard lock(mutex);
        return worked;
    }
};

} // namespace

TEST(NewestRequestWorker, WorksOnTheNewestRequestAndKeepsTheNewestResult) {
    GatedWorker gated;
    NewestRequestWorker<int, int>& worker = gated.worker;
    EXPECT_FALSE(worker.request(1)); // nothing waited
    gated.waitForTheFirst();         // 1 is held until the other requests are in
    EXPECT_FALSE(worker.request(2)); // 1 is worked on, not waiting
    // Replaces 2, which is never worked on and comes back to the caller (to use again).
    EXPECT_EQ(worker.request(3), std::optional<int>(2));
    EXPECT_FALSE(worker.idle());
    EXPECT_FALSE(worker.take()); // nothing finished yet
    gated.open();
    worker.waitUntilIdle();
    EXPECT_TRUE(worker.idle());
    EXPECT_EQ(gated.workedOn(), (std::vector<int>{1, 3}));
    const std::optional<int> result = worker.take();
    ASSERT_TRUE(result);
    EXPECT_EQ(*result, 30); // 1's result was replaced before it was taken
    EXPECT_FALSE(worker.take());
}

// cancel() drops the request waiting and returns once the work under way is done: what the
// recovery file's writer needs before the file is removed.
TEST(NewestRequestWorker, CancelDropsTheWaitingRequestAndWaitsForTheWorkUnderWay) {
    GatedWorker gated;
    NewestRequestWorker<int, int>& worker = gated.worker;
    worker.request(1);
    gated.waitForTheFirst();
    worker.request(2);
    std::future<std::optional<int>> cancelled =
        std::async(std::launch::async, [&] { return worker.cancel(); });
    EXPECT_EQ(cancelled.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout)
        << "cancel() returned while 1 was still worked on";
    gated.open();
    EXPECT_EQ(cancelled.get(), std::optional<int>(2)) << "the waiting request comes back";
    EXPECT_TRUE(worker.idle());
    EXPECT_EQ(gated.workedOn(), (std::vector<int>{1})) << "2 was never worked on";
    EXPECT_EQ(worker.take(), std::optional<int>(10));
    EXPECT_FALSE(worker.cancel()) << "nothing waits";
}
