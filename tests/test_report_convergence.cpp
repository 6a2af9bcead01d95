// The report's paired error (report/convergence.hpp): renders that share their random numbers,
// compared half by half, give the error a setting causes without the noise of either render.
// Synthetic images with a known bias and independent noise stand in for the renders.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

#include "report/convergence.hpp"

namespace {

// truth + bias + Gaussian noise of sd `sigma` in every channel of every pixel
lab::film::ImageRgb noisy(int size, float truth, float bias, float sigma, std::mt19937& rng) {
    std::normal_distribution<float> noise(0.0f, sigma);
    lab::film::ImageRgb image(size, size);
    for (float& v : image.rgb) v = truth + bias + noise(rng);
    return image;
}

}  // namespace

TEST_CASE("Paired error: a known bias comes back through noise twice its size, and no bias stays within the noise level", "[report]") {
    std::mt19937 rng(7);
    const int size = 128;
    const float truth = 1.0f, sigma = 0.1f;
    for (float bias : {0.0f, 0.02f, 0.05f}) {
        INFO("bias " << bias);
        const lab::film::ImageRgb b1 = noisy(size, truth, 0.0f, sigma, rng), b2 = noisy(size, truth, 0.0f, sigma, rng);
        const lab::film::ImageRgb a1 = noisy(size, truth, bias, sigma, rng), a2 = noisy(size, truth, bias, sigma, rng);
        const lab::report::PairedError e = lab::report::paired_relative_error(a1, a2, b1, b2);
        // the product's standard error is sigma_d^2 / sqrt(pixels) with sigma_d^2 = 2 sigma^2: the noise level
        // sqrt(2 se) is about 0.0126 here, a tenth of what the noise alone puts into an RMSE (0.14)
        CHECK(e.noise == Approx(std::sqrt(2.0 * 2.0 * sigma * sigma / size)).epsilon(0.1));
        if (bias == 0.0f)
            CHECK(e.relative <= e.noise);
        else
            CHECK(std::fabs(e.relative - bias / truth) <= 0.25 * bias / truth + e.noise * e.noise / (2.0 * bias));
    }
}

TEST_CASE("Paired error: images of different sizes are refused", "[report]") {
    lab::film::ImageRgb a(4, 4), b(4, 5);
    CHECK_THROWS_AS(lab::report::paired_relative_error(a, a, a, b), std::invalid_argument);
}
