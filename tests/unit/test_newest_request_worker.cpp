// The viewer's background worker (editor/newest_request_worker.hpp): a request that arrives
// while another is worked on replaces the one waiting, so only the newest is worked on next,
// and take() gives the newest finished result once.
#include "editor/newest_request_worker.hpp"

#include <gtest/gtest.h>

#include <future>
#include <mutex>
#include <vector>

using rmsc::editor::NewestRequestWorker;

TEST(NewestRequestWorker, WorksOnTheNewestRequestAndKeepsTheNewestResult) {
    std::promise<void> gate;
    std::shared_future<void> opened = gate.get_future().share();
    std::promise<void> firstStarted;
    std::mutex mutex;
    std::vector<int> worked;
    NewestRequestWorker<int, int> worker([&](int& request) {
        if (request == 1) {
            firstStarted.set_value();
            opened.wait(); // held until the other requests are in
        }
        std::lock_guard lock(mutex);
        worked.push_back(request);
        return request * 10;
    });
    EXPECT_FALSE(worker.request(1)); // nothing waited
    firstStarted.get_future().wait();
    EXPECT_FALSE(worker.request(2)); // 1 is worked on, not waiting
    // Replaces 2, which is never worked on and comes back to the caller (to use again).
    EXPECT_EQ(worker.request(3), std::optional<int>(2));
    EXPECT_FALSE(worker.idle());
    EXPECT_FALSE(worker.take()); // nothing finished yet
    gate.set_value();
    worker.waitUntilIdle();
    EXPECT_TRUE(worker.idle());
    EXPECT_EQ(worked, (std::vector<int>{1, 3}));
    const std::optional<int> result = worker.take();
    ASSERT_TRUE(result);
    EXPECT_EQ(*result, 30); // 1's result was replaced before it was taken
    EXPECT_FALSE(worker.take());
}
