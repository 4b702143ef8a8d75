// A worker thread that works on the newest request it was given: a request that arrives while
// another waits replaces it, and a finished result waits to be taken, replaced by a newer one.
// The viewer's background jobs (the scene's compile, its cells' pruning) are this with their
// own work; the work runs on the worker thread alone, so what it keeps between requests needs
// no lock.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace rmsc::editor {

template <class Request, class Result> class NewestRequestWorker {
  public:
    explicit NewestRequestWorker(std::function<Result(Request&)> work)
        : work_(std::move(work)), thread_([this] { run(); }) {}
    ~NewestRequestWorker() { // waits for the work under way
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        changed_.notify_all();
        thread_.join();
    }
    NewestRequestWorker(const NewestRequestWorker&) = delete;
    NewestRequestWorker& operator=(const NewestRequestWorker&) = delete;

    // Returns the request this one replaced, if one was waiting (its owner may use it again).
    std::optional<Request> request(Request request) {
        std::optional<Request> replaced;
        {
            std::lock_guard lock(mutex_);
            replaced = std::exchange(waiting_, std::move(request));
        }
        changed_.notify_all();
        return replaced;
    }
    // The newest finished result, once (nullopt while none is new).
    std::optional<Result> take() {
        std::lock_guard lock(mutex_);
        return std::exchange(finished_, std::nullopt);
    }
    // Nothing waits and nothing is worked on.
    bool idle() const {
        std::lock_guard lock(mutex_);
        return !waiting_ && !working_;
    }
    // Drops the request waiting (returned, for its owner to use again) and waits for the work
    // under way; its result can still be taken.
    std::optional<Request> cancel() {
        std::unique_lock lock(mutex_);
        std::optional<Request> dropped = std::exchange(waiting_, std::nullopt);
        changed_.wait(lock, [this] { return !working_; });
        return dropped;
    }
    void waitUntilIdle() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return !waiting_ && !working_; });
    }

  private:
    void run() {
        for (;;) {
            std::optional<Request> request;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [this] { return stopping_ || waiting_; });
                if (stopping_) return;
                request = std::exchange(waiting_, std::nullopt);
                working_ = true;
            }
            Result result = work_(*request);
            {
                std::lock_guard lock(mutex_);
                finished_ = std::move(result);
                working_ = false;
            }
            changed_.notify_all();
        }
    }

    std::function<Result(Request&)> work_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<Request> waiting_;
    std::optional<Result> finished_;
    bool working_ = false;
    bool stopping_ = false;
    std::thread thread_; // last: starts once the rest is made
};

} // namespace rmsc::editor
