// A fixed pool of std::threads working through task indices. Tasks write only to their own
// slots, so results do not depend on the thread count or the order tasks finish in.
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace lab {

// The threads the machine runs at once (at least 1): the default thread count of the host's loops.
inline int hardware_threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

inline void parallel_for(int count, int threads, const std::function<void(int)>& task) {
    std::atomic<int> next{0};
    auto worker = [&]() {
        for (int i = next++; i < count; i = next++) task(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
}

}  // namespace lab
