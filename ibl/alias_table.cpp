#include "ibl/alias_table.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace lab::ibl {

std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights) {
    const size_t n = weights.size();
    double sum = 0.0;
    for (double w : weights) {
        if (!(w >= 0.0)) throw std::invalid_argument("build_alias_table: weights must be non-negative");
        sum += w;
    }
    if (n == 0 || n > size_t(INT32_MAX) || !(sum > 0.0) || !std::isfinite(sum))
        throw std::invalid_argument("build_alias_table: weights need a positive finite sum");
    // Each cell's share of its entry's interval: n p. Cells below 1 take the rest of their entry
    // from a cell above 1 (Vose: every pairing empties one of the two lists, so n - 1 pairings).
    std::vector<double> scaled(n);
    std::vector<int> small, large;
    for (size_t k = 0; k < n; ++k) {
        scaled[k] = weights[k] / sum * double(n);
        (scaled[k] < 1.0 ? small : large).push_back(int(k));
    }
    std::vector<AliasEntry> table(n);
    while (!small.empty() && !large.empty()) {
        const int s = small.back(), l = large.back();
        small.pop_back();
        table[s] = AliasEntry{float(scaled[s]), l};
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What is left is 1 up to rounding: its own cell throughout.
    for (int k : small) table[k] = AliasEntry{1.0f, k};
    for (int k : large) table[k] = AliasEntry{1.0f, k};
    return table;
}

namespace {

constexpr int64_t kUniforms = int64_t(1) << 24;  // the floats k 2^-24, k = 0 .. 2^24 - 1

float uniform(int64_t k) { return float(k) * 0x1.0p-24f; }

// The least k in [lo, hi) for which `past(k)` holds, or hi; past must be false then true in k.
template <class Past>
int64_t first_past(int64_t lo, int64_t hi, Past past) {
    while (lo < hi) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (past(mid))
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

}  // namespace

std::vector<int64_t> alias_entry_starts(int n) {
    if (n <= 0 || int64_t(n) > kUniforms) throw std::invalid_argument("alias_entry_starts: needs 1 to 2^24 cells");
    std::vector<int64_t> starts(size_t(n) + 1);
    starts[0] = 0;
    for (int i = 0; i < n; ++i)
        starts[size_t(i) + 1] = first_past(starts[size_t(i)], kUniforms, [n, i](int64_t k) {
            float f;
            return ::ibl::alias_table_entry(n, uniform(k), &f) > i;
        });
    return starts;
}

std::vector<double> alias_table_probabilities(const AliasEntry* table, int n, const std::vector<int64_t>& starts) {
    if (n <= 0 || starts.size() != size_t(n) + 1) throw std::invalid_argument("alias_table_probabilities: starts do not match the table");
    std::vector<double> p(size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        const int64_t start = starts[size_t(i)], end = starts[size_t(i) + 1];
        const float threshold = table[i].threshold;
        const int64_t split = first_past(start, end, [n, threshold](int64_t k) {
            float f;
            ::ibl::alias_table_entry(n, uniform(k), &f);
            return !(f < threshold);
        });
        p[size_t(i)] += double(split - start) / double(kUniforms);
        p[size_t(table[i].alias)] += double(end - split) / double(kUniforms);
    }
    return p;
}

}  // namespace lab::ibl
