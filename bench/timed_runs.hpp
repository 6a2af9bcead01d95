// The limits every bench command puts on its render time and its repeats, checked in one place,
// and the median its repeated timings are reduced to.
#pragma once

#include <algorithm>
#include <vector>

#include "common/input_error.hpp"

namespace lab::cli {

// Throws lab::InputError naming the option unless 0 < seconds <= 3600.
inline void check_render_seconds(double seconds, const char* option = "--seconds") {
    if (!(seconds > 0.0 && seconds <= 3600.0)) throw InputError(option, "", "must be more than 0 and at most 3600");
}

// Throws lab::InputError naming --repeats unless 1 <= repeats <= 100.
inline void check_repeats(int repeats) {
    if (repeats < 1 || repeats > 100) throw InputError("--repeats", "", "must be in [1, 100]");
}

// The median of repeated timings (the mean of the middle two for an even count).
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace lab::cli
