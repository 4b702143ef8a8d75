// A loop over [0, count) on worker threads that stops early when asked to, reporting its
// progress: the passes of dual contouring and of the adaptive octree. Internal to rmsc_export.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rmsc::exporter {

// Runs body(i) for i in [0, count) on `threads` threads (the caller's among them). `progress`,
// when set, gets progressFrom + (progressTo - progressFrom) * the fraction done, serialized,
// about every percent. Returns false when `cancel` was set (some bodies may not have run).
template <class Body>
bool parallelFor(std::int64_t count, int threads, const std::atomic<bool>* cancel,
                 const std::function<void(double)>& progress, double progressFrom,
                 double progressTo, Body body) {
    std::atomic<std::int64_t> next{0};
    std::atomic<std::int64_t> done{0};
    std::mutex progressMutex;
    std::int64_t reportedStep = -1;
    const std::int64_t total = std::max<std::int64_t>(count, 1);
    auto work = [&] {
        for (;;) {
            if (cancel && cancel->load()) return;
            const std::int64_t i = next++;
            if (i >= count) return;
            body(i);
            const std::int64_t finished = ++done;
            if (progress) {
                const std::int64_t step = finished * 100 / total;
                std::lock_guard lock(progressMutex);
                if (step > reportedStep) {
                    reportedStep = step;
                    progress(progressFrom +
                             (progressTo - progressFrom) * double(finished) / double(total));
                }
            }
        }
    };
    std::vector<std::thread> pool;
    const int n = int(std::min<std::int64_t>(threads, total));
    for (int t = 1; t < n; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    return !(cancel && cancel->load());
}

} // namespace rmsc::exporter
