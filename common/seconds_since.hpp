// Wall-clock seconds since a steady-clock time point: what the renderer's budget, the batches'
// timings and the benches measure with.
#pragma once

#include <chrono>

namespace lab {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lab
