#include "viewer/latest_job.hpp"

#include <sys/resource.h>
#include <unistd.h>

namespace lab::viewer {

LatestJob::LatestJob() { thread_ = std::thread([this] { run(); }); }

LatestJob::~LatestJob() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        ++submitted_;  // the running job is stale now
    }
    wake_.notify_all();
    thread_.join();
}

void LatestJob::submit(Job job) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(job);
    ++submitted_;
    wake_.notify_all();
}

bool LatestJob::busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return running_ || pending_ != nullptr;
}

void LatestJob::run() {
    // Below the interface and the render worker (Linux gives each thread its own nice value): the
    // checks and lobe plots take a second of both cores after each edit, which would otherwise
    // delay the edit's first frame. Best effort: a refusal leaves the priority as it was.
    (void)setpriority(PRIO_PROCESS, id_t(gettid()), 10);
    for (;;) {
        Job job;
        uint64_t mine = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || pending_ != nullptr; });
            if (stop_) return;
            job = std::move(pending_);
            pending_ = nullptr;
            mine = submitted_;
            running_ = true;
        }
        job([this, mine] {
            std::lock_guard<std::mutex> lock(mutex_);
            return submitted_ != mine;
        });
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = false;
    }
}

}  // namespace lab::viewer
