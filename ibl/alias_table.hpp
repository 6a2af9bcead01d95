// Host side of the alias tables that ibl/alias_table.h samples.
#pragma once

#include <cstdint>
#include <vector>

#include "ibl/ibl.hpp"

namespace lab::ibl {

using AliasEntry = ::ibl::AliasEntry;

// Vose's construction, in double: the table for cells drawn with probabilities proportional to
// `weights` (non-negative, with a positive finite sum).
std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights);

// The generator's numbers u = k 2^-24, k = 0 .. 2^24 - 1 (kernels/rng.h), each as likely, fall in
// the n entries of a table of n cells in runs: entry i reads the k in [starts[i], starts[i + 1]).
// The n + 1 run boundaries, found by searching the sampler's own float arithmetic, which is
// monotone in u. They depend on n only, so every table of n cells shares them.
std::vector<int64_t> alias_entry_starts(int n);

// The probability with which alias_table_sample() draws each cell of `table` (n cells, `starts`
// from alias_entry_starts(n)) from those numbers: the count of the u that draw the cell over 2^24,
// exact, rounding included. Inside an entry's run, f grows with u, so the u that keep the entry's
// own cell are the run's first ones, up to a boundary found by search.
std::vector<double> alias_table_probabilities(const AliasEntry* table, int n, const std::vector<int64_t>& starts);

}  // namespace lab::ibl
