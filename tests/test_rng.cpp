// The path tracers' random numbers (kernels/rng.h): Philox4x32-10 reproduces the known-answer
// vectors of its authors' Random123 library, and the floats of the per-path xoshiro128** streams
// it seeds are uniform, successive draws of a path are independent, and the same draw of
// neighbouring pixels, samples and seeds is independent. Each chi-square check is also run on a
// generator broken in the way it is meant to catch, and must reject it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "single_source/host_vocabulary.hpp"
#include "validation/chi_square_distribution.hpp"

namespace rng {
using namespace single_source;
#include "kernels/rng.h"
}  // namespace rng

namespace {

using lab::validation::chi_square_survival;
using lab::validation::sidak_alpha;

rng::Philox4 philox(unsigned c0, unsigned c1, unsigned c2, unsigned c3, unsigned k0, unsigned k1) {
    rng::Philox4 c{{c0, c1, c2, c3}};
    return rng::philox4x32_10(c, k0, k1);
}

// The first kDraws numbers of the stream of (pixel, sample, seed), in draw order.
constexpr int kDraws = 16;
using Generator = std::function<void(unsigned pixel, unsigned sample, unsigned seed, float* u)>;

void kernel_rng(unsigned pixel, unsigned sample, unsigned seed, float* u) {
    rng::Rng r = rng::rng_make(pixel, sample, seed, 0u);
    for (int i = 0; i < kDraws; i += 4) {
        rng::float4 v = rng::rng_next4(&r);
        for (int k = 0; k < 4; ++k) u[i + k] = v[k];
    }
}

// Pearson's statistic of counts against equal expected counts, as its chi-square upper-tail
// probability (cells - 1 degrees of freedom).
double uniform_cells_p(const std::vector<double>& count) {
    double total = 0.0;
    for (double c : count) total += c;
    double expected = total / double(count.size()), chi2 = 0.0;
    for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
    return chi_square_survival(chi2, double(count.size() - 1));
}

constexpr unsigned kPixels = 1024, kSamples = 64;  // 65536 paths
constexpr double kSignificance = 1e-4;               // family-wise, per test case (Sidak over its checks)

// 1024 bins over [0, 1) of every number of every path (1M numbers, 1024 expected per bin).
double uniformity_p(const Generator& g) {
    std::vector<double> count(1024, 0.0);
    float u[kDraws];
    for (unsigned p = 0; p < kPixels; ++p)
        for (unsigned s = 0; s < kSamples; ++s) {
            g(p, s, 7u, u);
            for (float x : u) {
                if (!(x >= 0.0f && x < 1.0f)) return 0.0;
                count[int(x * 1024.0f)] += 1.0;
            }
        }
    return uniform_cells_p(count);
}

// 16x16 cells of the pairs (a, b): 65536 or 32768 pairs, 256 or 128 expected per cell.
struct PairCells {
    std::vector<double> count = std::vector<double>(256, 0.0);
    void add(float a, float b) { count[int(a * 16.0f) * 16 + int(b * 16.0f)] += 1.0; }
};

// Successive draws k, k+1 of one path, for every k (across rng_next4's groups of four too): one
// pair per path, so the pairs of one k are independent; the smallest p over k.
double successive_pairs_p(const Generator& g) {
    std::vector<PairCells> cells(kDraws - 1);
    float u[kDraws];
    for (unsigned p = 0; p < kPixels; ++p)
        for (unsigned s = 0; s < kSamples; ++s) {
            g(p, s, 7u, u);
            for (int k = 0; k + 1 < kDraws; ++k) cells[k].add(u[k], u[k + 1]);
        }
    double p_min = 1.0;
    for (const PairCells& c : cells) p_min = std::fmin(p_min, uniform_cells_p(c.count));
    return p_min;
}

// The same draw k of two streams that differ in one input: pixels 2i and 2i+1, samples 2j and 2j+1,
// seeds 7 and 8. The smallest p over the draws and the three neighbours.
double neighbour_streams_p(const Generator& g) {
    std::vector<PairCells> pixel(kDraws), sample(kDraws), seed(kDraws);
    float a[kDraws], b[kDraws];
    for (unsigned p = 0; p < kPixels; p += 2)
        for (unsigned s = 0; s < kSamples; ++s) {
            g(p, s, 7u, a);
            g(p + 1, s, 7u, b);
            for (int k = 0; k < kDraws; ++k) pixel[k].add(a[k], b[k]);
        }
    for (unsigned p = 0; p < kPixels; ++p)
        for (unsigned s = 0; s < kSamples; s += 2) {
            g(p, s, 7u, a);
            g(p, s + 1, 7u, b);
            for (int k = 0; k < kDraws; ++k) sample[k].add(a[k], b[k]);
        }
    for (unsigned p = 0; p < kPixels; p += 2)
        for (unsigned s = 0; s < kSamples; ++s) {
            g(p, s, 7u, a);
            g(p, s, 8u, b);
            for (int k = 0; k < kDraws; ++k) seed[k].add(a[k], b[k]);
        }
    double p_min = 1.0;
    for (const auto* group : {&pixel, &sample, &seed})
        for (const PairCells& c : *group) p_min = std::fmin(p_min, uniform_cells_p(c.count));
    return p_min;
}

// Each check's level: the family's significance shared by its sub-tests (Sidak).
double uniformity_alpha() { return kSignificance; }
double successive_alpha() { return sidak_alpha(kSignificance, kDraws - 1); }
double neighbour_alpha() { return sidak_alpha(kSignificance, 3 * kDraws); }

// Broken generators, each in the one way its check is for.
// 5 % of the numbers halved: an excess below 0.5 (uniformity).
void biased_rng(unsigned pixel, unsigned sample, unsigned seed, float* u) {
    kernel_rng(pixel, sample, seed, u);
    for (int i = 0; i < kDraws; ++i)
        if ((pixel * kDraws + i) % 20 == 0) u[i] *= 0.5f;
}
// A 32-bit LCG seeded by the path's Philox, its low bit rotated to the top: that bit alternates, so
// successive draws fall on opposite halves (successive pairs); uniform one at a time.
void lcg_low_bit_rng(unsigned pixel, unsigned sample, unsigned seed, float* u) {
    uint32_t x = philox(pixel, sample, 0, 0, seed, 0).v[0];
    for (int i = 0; i < kDraws; ++i) {
        x = x * 1664525u + 1013904223u;
        u[i] = rng::uint_to_unit_float((x << 31) | (x >> 1));
    }
}
// xoshiro128** seeded with (pixel, sample, seed, 0) itself instead of its Philox hash: the first
// draw is a function of the sample alone, the same for neighbouring pixels (neighbour streams).
void unhashed_seed_rng(unsigned pixel, unsigned sample, unsigned seed, float* u) {
    rng::Rng r;
    r.s0 = pixel;
    r.s1 = sample;
    r.s2 = seed;
    r.s3 = 0u;
    for (int i = 0; i < kDraws; ++i) u[i] = rng::uint_to_unit_float(rng::rng_next_uint(&r));
}

}  // namespace

TEST_CASE("Philox4x32-10 matches Random123's known-answer vectors", "[rng]") {
    rng::Philox4 zero = philox(0, 0, 0, 0, 0, 0);
    CHECK(zero.v[0] == 0x6627e8d5u);
    CHECK(zero.v[1] == 0xe169c58du);
    CHECK(zero.v[2] == 0xbc57ac4cu);
    CHECK(zero.v[3] == 0x9b00dbd8u);
    rng::Philox4 ones = philox(~0u, ~0u, ~0u, ~0u, ~0u, ~0u);
    CHECK(ones.v[0] == 0x408f276du);
    CHECK(ones.v[1] == 0x41c83b0eu);
    CHECK(ones.v[2] == 0xa20bc7c6u);
    CHECK(ones.v[3] == 0x6d5451fdu);
    rng::Philox4 pi = philox(0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u, 0xa4093822u, 0x299f31d0u);
    CHECK(pi.v[0] == 0xd16cfe09u);
    CHECK(pi.v[1] == 0x94fdccebu);
    CHECK(pi.v[2] == 0x5001e420u);
    CHECK(pi.v[3] == 0x24126ea1u);
}

TEST_CASE("xoshiro128** matches its reference implementation", "[rng]") {
    // Blackman and Vigna's xoshiro128starstar.c from the state {1, 2, 3, 4}: the first outputs,
    // worked by hand from the reference's update (result = rotl(s1 * 5, 7) * 9; then the state
    // {7, 0, 1026, 12288}, then {12295, 1029, 1029, 25165824}).
    rng::Rng r;
    r.s0 = 1u;
    r.s1 = 2u;
    r.s2 = 3u;
    r.s3 = 4u;
    CHECK(rng::rng_next_uint(&r) == 11520u);  // rotl(10, 7) * 9
    CHECK(rng::rng_next_uint(&r) == 0u);      // s1 after one step: 2 ^ (3 ^ 1) = 0
    CHECK(rng::rng_next_uint(&r) == 5927040u);
}

TEST_CASE("Floats fill the unit interval from 0 up and never reach 1", "[rng]") {
    CHECK(rng::uint_to_unit_float(0u) == 0.0f);
    CHECK(rng::uint_to_unit_float(~0u) == 1.0f - 0x1.0p-24f);
    CHECK(rng::uint_to_unit_float(~0u) < 1.0f);
}

TEST_CASE("The numbers are uniform, successive draws independent, neighbouring streams independent", "[rng]") {
    CHECK(uniformity_p(kernel_rng) > uniformity_alpha());
    CHECK(successive_pairs_p(kernel_rng) > successive_alpha());
    CHECK(neighbour_streams_p(kernel_rng) > neighbour_alpha());
}

TEST_CASE("Each independence check rejects a generator broken in its way", "[rng]") {
    CHECK(uniformity_p(biased_rng) < uniformity_alpha());
    CHECK(successive_pairs_p(lcg_low_bit_rng) < successive_alpha());
    CHECK(neighbour_streams_p(unhashed_seed_rng) < neighbour_alpha());
    // the LCG's numbers are uniform one at a time: only the pairs show its flaw
    CHECK(uniformity_p(lcg_low_bit_rng) > uniformity_alpha());
}

TEST_CASE("The same pixel, sample and seed give the same numbers - another seed does not", "[rng]") {
    rng::Rng a = rng::rng_make(17, 3, 99u, 0u), b = rng::rng_make(17, 3, 99u, 0u), c = rng::rng_make(17, 3, 100u, 0u);
    rng::float4 x = rng::rng_next4(&a), y = rng::rng_next4(&b), z = rng::rng_next4(&c);
    CHECK(x == y);
    CHECK(x != z);
    CHECK(rng::rng_next4(&a) != x);  // the next draw moves on
    // the stream is Philox's output of (pixel, sample, 0, 0) under the key (seed_lo, seed_hi)
    rng::Rng d = rng::rng_make(17, 3, 99u, 5u);
    rng::Philox4 seedwords = philox(17, 3, 0, 0, 99u, 5u);
    CHECK(d.s0 == seedwords.v[0]);
    CHECK(d.s1 == seedwords.v[1]);
    CHECK(d.s2 == seedwords.v[2]);
    CHECK(d.s3 == seedwords.v[3]);
}
