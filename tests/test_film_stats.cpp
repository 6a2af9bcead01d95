// Image statistics and errors against a reference, on images made by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "film/image_stats.hpp"

using lab::film::ImageRgb;

TEST_CASE("means are per channel over finite pixels - non-finite pixels are counted", "[film]") {
    ImageRgb image(2, 2);
    image.set(0, 0, 1.0f, 2.0f, 3.0f);
    image.set(1, 0, 3.0f, 0.0f, 1.0f);
    image.set(0, 1, 2.0f, 4.0f, -1.0f);
    image.set(1, 1, 5.0f, std::numeric_limits<float>::quiet_NaN(), 5.0f);
    lab::film::ImageStats s = lab::film::image_stats(image);
    CHECK(s.finite_pixels == 3u);
    CHECK(s.non_finite_pixels == 1u);
    CHECK(s.mean[0] == Approx(2.0));
    CHECK(s.mean[1] == Approx(2.0));
    CHECK(s.mean[2] == Approx(1.0));
    image.set(0, 0, std::numeric_limits<float>::infinity(), 0.0f, 0.0f);
    CHECK(lab::film::image_stats(image).non_finite_pixels == 2u);
    CHECK(lab::film::image_stats(ImageRgb(3, 1)).mean[1] == 0.0);
}

TEST_CASE("RMSE per channel, its mean, and relative to the reference's mean", "[film]") {
    ImageRgb reference(2, 1), image(2, 1);
    reference.set(0, 0, 1.0f, 2.0f, 4.0f);
    reference.set(1, 0, 1.0f, 2.0f, 4.0f);
    image.set(0, 0, 1.5f, 1.0f, 4.0f);  // differences (+0.5, -1, 0)
    image.set(1, 0, 0.5f, 3.0f, 4.75f); //             (-0.5, +1, 0.75)
    lab::film::ImageError e = lab::film::image_error(image, reference);
    CHECK(e.rmse[0] == Approx(0.5));
    CHECK(e.rmse[1] == Approx(1.0));
    CHECK(e.rmse[2] == Approx(std::sqrt(0.75 * 0.75 / 2.0)));
    CHECK(e.rmse_mean == Approx((0.5 + 1.0 + std::sqrt(0.28125)) / 3.0));
    CHECK(e.relative_rmse[0] == Approx(0.5));
    CHECK(e.relative_rmse[1] == Approx(0.5));
    CHECK(e.relative_rmse[2] == Approx(std::sqrt(0.28125) / 4.0));
    CHECK(e.relative_rmse_mean == Approx((0.5 + 0.5 + std::sqrt(0.28125) / 4.0) / 3.0));
    // against itself: 0, also for a black channel
    lab::film::ImageError zero = lab::film::image_error(ImageRgb(2, 2), ImageRgb(2, 2));
    CHECK(zero.rmse_mean == 0.0);
    CHECK(zero.relative_rmse_mean == 0.0);
    // an error on a black reference channel is infinitely large relatively
    ImageRgb grey(1, 1);
    grey.set(0, 0, 0.5f, 0.0f, 0.0f);
    CHECK(std::isinf(lab::film::image_error(grey, ImageRgb(1, 1)).relative_rmse[0]));
}

TEST_CASE("a NaN shows in the error - images of different sizes are refused", "[film]") {
    ImageRgb reference(3, 2), image(3, 2);
    image.set(2, 1, 0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f);
    lab::film::ImageError e = lab::film::image_error(image, reference);
    CHECK(e.rmse[0] == 0.0);
    CHECK(std::isnan(e.rmse[1]));
    CHECK(std::isnan(e.rmse_mean));
    try {
        lab::film::image_error(ImageRgb(4, 3), ImageRgb(5, 3));
        FAIL("no error for different sizes");
    } catch (const std::invalid_argument& err) {
        CHECK(std::string(err.what()) == "image sizes differ: 4x3 and 5x3");
    }
    ImageRgb broken(2, 2);
    broken.rgb.pop_back();
    CHECK_THROWS_AS(lab::film::image_stats(broken), std::invalid_argument);
}
