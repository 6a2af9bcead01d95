// The stability atlas's integrator entry (report/strategy_shares.hpp): strategies grouped by the
// integrator that has them too, and each group's share of a pixel's luminance, on images whose
// shares are known by construction. (That the weighted strategies sum to the BDPT image is
// tests/cli/expect_strategy_images.cmake's check.)
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "report/strategy_shares.hpp"

using lab::report::StrategyGroup;

namespace {

// A width x 1 image, every pixel grey (r = g = b, so its luminance is the value) at `values`.
lab::film::ImageRgb grey_row(const std::vector<float>& values) {
    lab::film::ImageRgb image(int(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) image.rgb[3 * i + size_t(c)] = values[i];
    return image;
}

}  // namespace

TEST_CASE("Strategy groups: s <= 1 the path tracer's, t = 1 light tracing's, the rest connections", "[report][strategies]") {
    CHECK(lab::report::strategy_group(0, 2) == StrategyGroup::path_tracer);  // a camera path reaching a light
    CHECK(lab::report::strategy_group(1, 4) == StrategyGroup::path_tracer);  // next-event estimation
    CHECK(lab::report::strategy_group(2, 1) == StrategyGroup::light_tracer);
    CHECK(lab::report::strategy_group(4, 1) == StrategyGroup::light_tracer);
    CHECK(lab::report::strategy_group(2, 2) == StrategyGroup::connection);
    CHECK(lab::report::strategy_group(3, 2) == StrategyGroup::connection);
    CHECK_THROWS_AS(lab::report::strategy_group(0, 1), std::invalid_argument);  // one vertex: no path
    CHECK_THROWS_AS(lab::report::strategy_group(2, 0), std::invalid_argument);  // no camera vertex
    CHECK_THROWS_AS(lab::report::strategy_group(-1, 3), std::invalid_argument);
}

TEST_CASE("Strategy shares: each group's share of the light, per pixel and in all, on images of known shares", "[report][strategies]") {
    // pixel 0: the path tracer's 0.9, light tracing's 0.05, connections 0.05 of 1;
    // pixel 1: light tracing's 2 alone; pixel 2: nothing (unlit); pixel 3: the path tracer's 1, connections 1
    const std::vector<lab::report::WeightedStrategy> strategies = {
        {1, 2, grey_row({0.6f, 0.0f, 0.0f, 1.0f})},  // path tracer
        {0, 3, grey_row({0.3f, 0.0f, 0.0f, 0.0f})},  // path tracer
        {2, 1, grey_row({0.05f, 2.0f, 0.0f, 0.0f})}, // light tracing
        {2, 2, grey_row({0.05f, 0.0f, 0.0f, 1.0f})}, // connection
    };
    const lab::report::StrategyShares shares = lab::report::strategy_shares(strategies);
    const double total = 1.0 + 2.0 + 2.0;
    const size_t pt = size_t(StrategyGroup::path_tracer), lt = size_t(StrategyGroup::light_tracer), cn = size_t(StrategyGroup::connection);
    CHECK(shares.light[pt] == Approx(1.9 / total));
    CHECK(shares.light[lt] == Approx(2.05 / total));
    CHECK(shares.light[cn] == Approx(1.05 / total));
    CHECK(shares.lit_pixels == Approx(0.75));
    // under a tenth: the path tracer's in pixel 1; light tracing's in pixels 0 and 3; connections in 0 and 1
    CHECK(shares.minor_pixels[pt] == Approx(1.0 / 3.0));
    CHECK(shares.minor_pixels[lt] == Approx(2.0 / 3.0));
    CHECK(shares.minor_pixels[cn] == Approx(2.0 / 3.0));
    // the map: red light tracing's, green connections', blue the path tracer's
    const std::array<float, 3> p0 = shares.groups.at(0, 0), p1 = shares.groups.at(1, 0), p2 = shares.groups.at(2, 0), p3 = shares.groups.at(3, 0);
    CHECK(p0[0] == Approx(0.05f));
    CHECK(p0[1] == Approx(0.05f));
    CHECK(p0[2] == Approx(0.9f));
    CHECK((p1[0] == 1.0f && p1[1] == 0.0f && p1[2] == 0.0f));
    CHECK((p2[0] == 0.0f && p2[1] == 0.0f && p2[2] == 0.0f));
    CHECK((p3[0] == 0.0f && p3[1] == Approx(0.5f) && p3[2] == Approx(0.5f)));
    // the sum is the BDPT image; every strategy's share in the order given
    CHECK(shares.image.at(0, 0)[1] == Approx(1.0f));
    CHECK(shares.image.at(1, 0)[1] == Approx(2.0f));
    REQUIRE(shares.strategies.size() == 4);
    CHECK(shares.strategies[0].share == Approx(1.6 / total));
    CHECK((shares.strategies[2].s == 2 && shares.strategies[2].t == 1));
    CHECK(shares.strategies[2].share == Approx(2.05 / total));
}

TEST_CASE("Strategy shares: no strategies, images of different sizes and negative or NaN pixels are refused", "[report][strategies]") {
    CHECK_THROWS_AS(lab::report::strategy_shares({}), std::invalid_argument);
    CHECK_THROWS_AS(lab::report::strategy_shares({{1, 2, grey_row({1.0f})}, {2, 1, grey_row({1.0f, 1.0f})}}), std::invalid_argument);
    CHECK_THROWS_AS(lab::report::strategy_shares({{1, 2, grey_row({-1.0f})}}), std::invalid_argument);
    CHECK_THROWS_AS(lab::report::strategy_shares({{1, 2, grey_row({std::nanf("")})}}), std::invalid_argument);
    CHECK_THROWS_AS(lab::report::strategy_shares({{0, 1, grey_row({1.0f})}}), std::invalid_argument);
}
