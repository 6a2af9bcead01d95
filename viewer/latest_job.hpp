// A background thread that runs only the newest job: submitting a job replaces any that has not
// started, and tells the running one it is stale (its `cancelled()` turns true), so an edit made
// while the checks of an older one run never waits behind them. Jobs publish their own results.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace lab::viewer {

class LatestJob {
public:
    using Cancelled = std::function<bool()>;
    using Job = std::function<void(const Cancelled&)>;
    LatestJob();
    ~LatestJob();  // cancels the running job and waits for it
    LatestJob(const LatestJob&) = delete;
    LatestJob& operator=(const LatestJob&) = delete;
    void submit(Job job);
    bool busy() const;

private:
    void run();
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    Job pending_;
    uint64_t submitted_ = 0;  // counts submissions; a job is stale once it is no longer the last
    bool running_ = false, stop_ = false;
    std::thread thread_;
};

}  // namespace lab::viewer
