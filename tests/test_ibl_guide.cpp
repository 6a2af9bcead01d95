// The guide tables of the environment's cdfs (ibl/distribution2d.h): a guided search returns the very
// cell and offset the binary search over the whole cdf returns, for every u, so sampling through
// them changes no sample, no density and no image. Checked at every bucket edge (m / G and the
// float below it), at the ends of [0, 1) and beyond, and at random u, on every cdf of three
// environments: courtyard (face 256), a strong-contrast one with black rows (the floor and the
// fallback), and a black one (the uniform fallback).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ibl/distribution.hpp"
#include "ibl/environment.hpp"
#include "ibl/ibl.hpp"
#include "validation/uniform_random.hpp"

using lab::ibl::Environment;
namespace validation = lab::validation;

namespace {

// The u worth checking for a guide of `guide_size` buckets: each bucket's start and the float below
// it, the ends, values outside [0, 1), and `random` uniform ones.
std::vector<float> probes(int guide_size, int random, validation::UniformRandom& rng) {
    std::vector<float> u{0.0f, -0.0f, -1.0f, 1.0f, 2.0f, DISTRIBUTION_ONE_MINUS_EPSILON, std::numeric_limits<float>::quiet_NaN()};
    for (int m = 1; m < guide_size; ++m) {
        const float start = float(m) / float(guide_size);
        u.push_back(start);
        u.push_back(std::nextafter(start, 0.0f));
    }
    for (int k = 0; k < random; ++k) u.push_back(rng.next_float());
    return u;
}

// Mismatches of the guided search against the full one on one cdf of n cells; the first is described.
long mismatches(const float* cdf, const unsigned short* guide, int guide_size, int n, int random, validation::UniformRandom& rng,
                std::string* first) {
    long bad = 0;
    for (float u : probes(guide_size, random, rng)) {
        float full_offset = -1.0f, guided_offset = -1.0f;
        const int full = ibl::distribution1d_sample(cdf, n, u, &full_offset);
        const int guided = ibl::distribution1d_sample_guided(cdf, guide, guide_size, n, u, &guided_offset);
        if (full != guided || full_offset != guided_offset) {
            if (bad++ == 0)
                *first = "u " + std::to_string(u) + ": cell " + std::to_string(full) + " offset " + std::to_string(full_offset) +
                         ", guided cell " + std::to_string(guided) + " offset " + std::to_string(guided_offset);
        }
    }
    return bad;
}

void check_environment(const Environment& env, const char* what) {
    const int n = env.face_size(), rows = 6 * n;
    const int row_guide = env.map().row_guide_size, column_guide = env.map().column_guide_size;
    REQUIRE(row_guide == ibl::distribution_guide_size(rows));
    REQUIRE(column_guide == ibl::distribution_guide_size(n));
    REQUIRE(env.guide().size() == size_t(row_guide) + size_t(rows) * column_guide);
    validation::UniformRandom rng(77);
    std::string first;
    long bad = mismatches(env.marginal_cdf().data(), env.guide().data(), row_guide, rows, 20000, rng, &first);
    for (int r = 0; r < rows; ++r)
        bad += mismatches(env.conditional_cdf().data() + size_t(r) * (n + 1), env.guide().data() + row_guide + size_t(r) * column_guide,
                          column_guide, n, 8, rng, &first);
    INFO(what << ": first mismatch " << first);
    CHECK(bad == 0);
}

}  // namespace

TEST_CASE("ibl: the guide tables find the cell the full binary search finds", "[ibl][guide]") {
    check_environment(lab::ibl::load_environment("envmaps/courtyard.exr"), "courtyard");

    lab::ibl::LatLongImage contrast;  // a sun, a bright band and black rows
    contrast.width = 64;
    contrast.height = 32;
    contrast.rgb.assign(size_t(64) * 32 * 3, 0.0f);
    for (int x = 0; x < 64; ++x)
        for (int y = 0; y < 16; ++y) contrast.rgb[(size_t(y) * 64 + x) * 3] = (x == 20 && y == 9) ? 1e5f : (x >= 40 && x < 48 ? 5.0f : 0.1f);
    lab::ibl::EnvironmentOptions options;
    options.face_size = 24;  // not a power of two: guides of 256 and 32 entries
    check_environment(Environment::from_image(contrast, "contrast", options), "contrast");

    check_environment(lab::ibl::load_environment("constant:0,0,0"), "black");
}

TEST_CASE("ibl: a guide table over cells of zero width", "[ibl][guide]") {
    // cells 1 and 3 have probability 0: never chosen, by either search
    const std::vector<float> cdf{0.0f, 0.25f, 0.25f, 1.0f, 1.0f};
    std::vector<unsigned short> guide;
    lab::ibl::append_cdf_guide(cdf.data(), 4, 8, &guide);
    CHECK(guide == std::vector<unsigned short>{0, 0, 2, 2, 2, 2, 2, 2});
    validation::UniformRandom rng(3);
    std::string first;
    CHECK(mismatches(cdf.data(), guide.data(), 8, 4, 1000, rng, &first) == 0);
    CHECK_THROWS_AS(lab::ibl::append_cdf_guide(cdf.data(), 4, 6, &guide), std::invalid_argument);  // not a power of two
    CHECK_THROWS_AS(lab::ibl::append_cdf_guide(cdf.data(), 4, 2, &guide), std::invalid_argument);  // fewer entries than cells
}
