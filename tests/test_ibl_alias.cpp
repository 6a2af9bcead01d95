// The alias tables that draw the environment's texels (ibl/alias_table.h). Every one of the 2^24
// numbers the generator gives (k 2^-24, kernels/rng.h) is put through the sampler, so the counts are
// the probabilities the sampler realises, exactly:
//  - they must equal alias_table_probabilities(), which the host stores in the texels' w for
//    environment_pdf() (so a sample's density is the probability it was drawn with, rounding
//    included);
//  - they must be the weights' probabilities up to the rounding of the sampler's float arithmetic:
//    each part of [0, 1) that draws a cell (its own entry's kept share, and the share of each entry
//    whose alias it is) has two ends, each of which rounding moves by at most one number, and holds
//    a whole count of numbers: at most 4 2^-24 off per part, a bound from the arithmetic alone;
//  - the offset returned inside a cell must be uniform: a quarter of the cell's numbers in each
//    quarter of [0, 1), up to 2 numbers per part.
// A table with its aliases shifted by one, or its thresholds 1 % low, fails the second check.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "ibl/alias_table.hpp"
#include "ibl/distribution.hpp"
#include "ibl/ibl.hpp"
#include "validation/uniform_random.hpp"

using lab::ibl::AliasEntry;

namespace {

constexpr int64_t kNumbers = int64_t(1) << 24;

struct Enumeration {
    std::vector<int64_t> count;                 // per cell: the numbers that draw it
    std::vector<std::vector<int64_t>> quarter;  // per cell: of those, the ones whose offset is in each quarter of [0, 1)
    bool offsets_in_range = true;               // every offset in [0, 1)
};

Enumeration enumerate(const std::vector<AliasEntry>& table) {
    const int n = int(table.size());
    Enumeration e;
    e.count.assign(size_t(n), 0);
    e.quarter.assign(size_t(n), std::vector<int64_t>(4, 0));
    for (int64_t k = 0; k < kNumbers; ++k) {
        float offset = -1.0f;
        const int cell = ::ibl::alias_table_sample(table.data(), n, float(k) * 0x1.0p-24f, &offset);
        ++e.count[size_t(cell)];
        if (!(offset >= 0.0f && offset < 1.0f)) {
            e.offsets_in_range = false;
            continue;
        }
        ++e.quarter[size_t(cell)][size_t(offset * 4.0f)];
    }
    return e;
}

// The parts of [0, 1) that draw each cell: its own entry's (if it keeps any share) and one per entry
// that names it as alias (if that entry gives any share away).
std::vector<int> parts(const std::vector<AliasEntry>& table) {
    std::vector<int> p(table.size(), 0);
    for (size_t i = 0; i < table.size(); ++i) {
        if (table[i].threshold > 0.0f) ++p[i];
        if (table[i].threshold < 1.0f) ++p[size_t(table[i].alias)];
    }
    return p;
}

// Cells whose realised probability is further from its weight's than the rounding bound; the first
// is described.
long off_target(const std::vector<double>& weights, const std::vector<AliasEntry>& table, const Enumeration& e, std::string* first) {
    double sum = 0.0;
    for (double w : weights) sum += w;
    const std::vector<int> part = parts(table);
    long bad = 0;
    for (size_t c = 0; c < weights.size(); ++c) {
        const double realised = double(e.count[c]) / double(kNumbers), target = weights[c] / sum;
        const double bound = 4.0 * double(part[c]) * 0x1.0p-24;
        if (std::fabs(realised - target) > bound && bad++ == 0)
            *first = "cell " + std::to_string(c) + ": drawn with " + std::to_string(realised) + ", weight's probability " +
                     std::to_string(target) + ", bound " + std::to_string(bound);
    }
    return bad;
}

std::vector<std::vector<double>> weight_cases() {
    std::vector<std::vector<double>> cases;
    cases.push_back(std::vector<double>(5, 1.0));  // uniform: every threshold 1
    lab::validation::UniformRandom rng(11);
    std::vector<double> random(24);
    for (double& w : random) w = rng.next_double() < 0.2 ? 0.0 : std::pow(10.0, 4.0 * rng.next_double());  // zeros and four decades
    cases.push_back(random);
    std::vector<double> sun(37, 1.0);  // one cell with nearly all the weight: it is every other entry's alias
    sun[17] = 1e6;
    cases.push_back(sun);
    std::vector<double> falling(256);  // a row's worth of texels, smoothly darker with a few bright ones
    for (int k = 0; k < 256; ++k) falling[size_t(k)] = std::exp(-k / 40.0) * (k % 37 == 0 ? 50.0 : 1.0);
    cases.push_back(falling);
    for (std::vector<double>& w : cases) w = lab::ibl::floored_weights(w);
    return cases;
}

}  // namespace

TEST_CASE("ibl: an alias table draws each cell with the probability stored for it, over every number of the generator",
          "[ibl][alias]") {
    for (const std::vector<double>& weights : weight_cases()) {
        const int n = int(weights.size());
        const std::vector<AliasEntry> table = lab::ibl::build_alias_table(weights);
        REQUIRE(table.size() == weights.size());
        const Enumeration e = enumerate(table);
        const std::vector<double> stored = lab::ibl::alias_table_probabilities(table.data(), n, lab::ibl::alias_entry_starts(n));
        long differs = 0;
        for (int c = 0; c < n; ++c) differs += stored[size_t(c)] != double(e.count[size_t(c)]) / double(kNumbers);
        std::string first;
        const long far = off_target(weights, table, e, &first);
        const std::vector<int> part = parts(table);
        long uneven = 0;
        for (int c = 0; c < n; ++c)
            for (int q = 0; q < 4; ++q) {
                const double expected = double(e.count[size_t(c)]) / 4.0;
                uneven += std::fabs(double(e.quarter[size_t(c)][size_t(q)]) - expected) > 2.0 * part[size_t(c)] + 1.0;
            }
        INFO(n << " cells: " << differs << " stored probabilities differ from the counts, " << far << " off the weights (first: " << first
               << "), " << uneven << " uneven quarters of the offset");
        CHECK(differs == 0);
        CHECK(far == 0);
        CHECK(uneven == 0);
        CHECK(e.offsets_in_range);
    }
}

TEST_CASE("ibl: the alias check rejects shifted aliases and low thresholds", "[ibl][alias]") {
    const std::vector<double> weights = weight_cases()[1];
    const int n = int(weights.size());
    std::vector<AliasEntry> shifted = lab::ibl::build_alias_table(weights), low = shifted;
    for (AliasEntry& entry : shifted) entry.alias = (entry.alias + 1) % n;
    for (AliasEntry& entry : low) entry.threshold *= 0.99f;
    std::string first;
    CHECK(off_target(weights, shifted, enumerate(shifted), &first) > 0);
    CHECK(off_target(weights, low, enumerate(low), &first) > 0);
}

TEST_CASE("ibl: an alias table needs non-negative weights with a positive finite sum", "[ibl][alias]") {
    CHECK_THROWS_AS(lab::ibl::build_alias_table({}), std::invalid_argument);
    CHECK_THROWS_AS(lab::ibl::build_alias_table({0.0, 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(lab::ibl::build_alias_table({1.0, -1.0, 2.0}), std::invalid_argument);
    CHECK_THROWS_AS(lab::ibl::build_alias_table({1.0, std::nan("")}), std::invalid_argument);
    CHECK_THROWS_AS(lab::ibl::build_alias_table({1.0, INFINITY}), std::invalid_argument);
    const std::vector<AliasEntry> one = lab::ibl::build_alias_table({3.0});
    REQUIRE(one.size() == 1);
    CHECK(one[0].threshold == 1.0f);
    CHECK(one[0].alias == 0);
}

// The two-level tables over a grid that is no cube map (3 rows of 5 texels), as an image's texels
// are: each texel's probability must be its luminance x measure over the grid's sum, up to the
// sampler's rounding (4 2^-24 per part, at most 2 parts per level as above: within 16 2^-24 plus
// the floor's n 2^-22 share) and the row without light must get the floor's share. A builder that
// ignored the measure misses the first check by a factor of up to 5.
TEST_CASE("ibl: row alias tables draw each texel of a grid by luminance x measure", "[ibl][alias]") {
    const int rows = 3, columns = 5;
    std::vector<single_source::float4> texels(size_t(rows) * columns);
    auto measure = [](int, int i) { return 1.0 + i; };
    double total = 0.0;
    std::vector<double> expected(texels.size());
    for (int r = 0; r < rows; ++r)
        for (int i = 0; i < columns; ++i) {
            const float v = r == 1 ? 0.0f : float(1 + (r * columns + i) % 4);
            texels[size_t(r) * columns + i] = single_source::float4(v, v, v, 0.0f);
            expected[size_t(r) * columns + i] = lab::ibl::luminance(v, v, v) * measure(r, i);
            total += expected[size_t(r) * columns + i];
        }
    const std::vector<AliasEntry> alias = lab::ibl::build_row_alias_tables(texels, rows, columns, measure);
    REQUIRE(alias.size() == size_t(rows) * (columns + 1));
    const std::vector<float> p = lab::ibl::row_texel_probabilities(alias, rows, columns);
    const double tolerance = 16.0 * 0x1.0p-24 + columns * rows * lab::ibl::kSamplingFloor;
    double sum = 0.0;
    for (size_t t = 0; t < p.size(); ++t) {
        INFO("texel " << t);
        CHECK(std::fabs(p[t] - expected[t] / total) <= tolerance);
        sum += p[t];
    }
    CHECK(std::fabs(sum - 1.0) <= 1e-6);
    CHECK_THROWS_AS(lab::ibl::build_row_alias_tables(texels, rows, columns + 1, measure), std::invalid_argument);
}
