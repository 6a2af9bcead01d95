// The counter-based generator (kernels/rng.h): Philox4x32-10 reproduces the known-answer vectors of
// its authors' Random123 library, and the floats it gives are uniform and independent across
// pixels, samples and draws.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "single_source/host_vocabulary.hpp"

namespace rng {
using namespace single_source;
#include "kernels/rng.h"
}  // namespace rng

namespace {

rng::Philox4 philox(unsigned c0, unsigned c1, unsigned c2, unsigned c3, unsigned k0, unsigned k1) {
    rng::Philox4 c{{c0, c1, c2, c3}};
    return rng::philox4x32_10(c, k0, k1);
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

TEST_CASE("Random floats are uniform below 1 and streams are independent", "[rng]") {
    // 64 bins over [0, 1) from 256 pixels x 64 samples x 4 draws x 4 numbers: chi-square with 63
    // degrees of freedom; 130 is beyond its 1e-6 quantile.
    const int bins = 64;
    std::vector<double> count(bins, 0.0);
    double sum_xy = 0.0, sum_x = 0.0, sum_y = 0.0, sum_xx = 0.0, sum_yy = 0.0;
    long n = 0, pairs = 0;
    for (unsigned pixel = 0; pixel < 256; ++pixel)
        for (unsigned sample = 0; sample < 64; ++sample) {
            rng::Rng r = rng::rng_make(pixel, sample, 1234u, 0u);
            rng::Rng neighbour = rng::rng_make(pixel + 1, sample, 1234u, 0u);
            for (int draw = 0; draw < 4; ++draw) {
                rng::float4 u = rng::rng_next4(&r);
                rng::float4 v = rng::rng_next4(&neighbour);
                for (int k = 0; k < 4; ++k) {
                    REQUIRE(u[k] >= 0.0f);
                    REQUIRE(u[k] < 1.0f);
                    count[int(u[k] * bins)] += 1.0;
                    ++n;
                    // correlation between the same draw of neighbouring pixels
                    sum_x += u[k];
                    sum_y += v[k];
                    sum_xy += double(u[k]) * v[k];
                    sum_xx += double(u[k]) * u[k];
                    sum_yy += double(v[k]) * v[k];
                    ++pairs;
                }
            }
        }
    double expected = double(n) / bins, chi2 = 0.0;
    for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
    CHECK(chi2 < 130.0);
    double cov = sum_xy / pairs - (sum_x / pairs) * (sum_y / pairs);
    double corr = cov / std::sqrt((sum_xx / pairs - std::pow(sum_x / pairs, 2)) * (sum_yy / pairs - std::pow(sum_y / pairs, 2)));
    CHECK(std::fabs(corr) < 5.0 / std::sqrt(double(pairs)));  // 5 standard errors of a zero correlation
}

TEST_CASE("The same pixel, sample and seed give the same numbers - another seed does not", "[rng]") {
    rng::Rng a = rng::rng_make(17, 3, 99u, 0u), b = rng::rng_make(17, 3, 99u, 0u), c = rng::rng_make(17, 3, 100u, 0u);
    rng::float4 x = rng::rng_next4(&a), y = rng::rng_next4(&b), z = rng::rng_next4(&c);
    CHECK(x == y);
    CHECK(x != z);
    CHECK(rng::rng_next4(&a) != x);  // the next draw moves on
}
