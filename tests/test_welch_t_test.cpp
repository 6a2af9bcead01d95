// Welch's t-test (validation/welch_t_test.hpp) against closed forms of Student's t, and its error
// rates on samples of known distribution: a level-alpha test rejects equal means in about alpha of
// the trials (binomial noise) and a real difference in nearly all.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "film/image.hpp"
#include "validation/region_t_test.hpp"
#include "validation/uniform_random.hpp"
#include "validation/welch_t_test.hpp"

using lab::validation::student_t_two_sided;
using lab::validation::welch_t_test;

namespace {

// A standard normal by Box-Muller.
double normal(lab::validation::UniformRandom& rng) {
    double u1 = std::fmax(double(rng.uniform(0.0f, 1.0f)), 1e-12), u2 = rng.uniform(0.0f, 1.0f);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace

TEST_CASE("Student's t two-sided tail matches its closed forms", "[validation][welch]") {
    // dof 1 is the Cauchy distribution: P(|T| >= t) = 1 - (2 / pi) atan(t)
    for (double t : {0.0, 0.5, 1.0, 3.0, 40.0}) CHECK(student_t_two_sided(t, 1.0) == Approx(1.0 - 2.0 / M_PI * std::atan(t)).epsilon(1e-10));
    // dof 2: P(|T| >= t) = 1 - t / sqrt(2 + t^2)
    for (double t : {0.1, 1.0, 2.5, 10.0}) CHECK(student_t_two_sided(t, 2.0) == Approx(1.0 - t / std::sqrt(2.0 + t * t)).epsilon(1e-10));
    // large dof: the normal's two-sided tail, erfc(t / sqrt 2), to O(1/dof)
    CHECK(student_t_two_sided(1.959963985, 1e7) == Approx(0.05).epsilon(1e-5));
    CHECK(student_t_two_sided(-2.0, 2.0) == student_t_two_sided(2.0, 2.0));
}

TEST_CASE("Welch's t-test rejects equal means at its level and finds a real difference", "[validation][welch]") {
    lab::validation::UniformRandom rng(99);
    const int trials = 2000, n_a = 8, n_b = 12;
    const double alpha = 0.05;
    int false_rejections = 0, detections = 0;
    for (int k = 0; k < trials; ++k) {
        std::vector<double> a(n_a), b(n_b), c(n_b);
        for (double& x : a) x = 1.0 + 0.1 * normal(rng);
        for (double& x : b) x = 1.0 + 0.3 * normal(rng);    // the same mean, another variance
        for (double& x : c) x = 1.25 + 0.3 * normal(rng);   // a mean 0.25 higher: about 2.6 standard errors
        false_rejections += welch_t_test(a, b).p_value < alpha;
        detections += welch_t_test(a, c).p_value < alpha;
    }
    // Binomial(2000, 0.05): mean 100, standard deviation 9.7; four of them either way. Welch's test
    // is approximate (its dof is estimated), so its size is near, not exactly, alpha.
    INFO("false rejections " << false_rejections << " of " << trials << ", detections " << detections);
    CHECK(std::abs(false_rejections - 100) <= 39);
    CHECK(detections > trials * 0.6);
    // exact cases
    CHECK(welch_t_test({1, 1, 1}, {1, 1}).p_value == 1.0);
    CHECK(welch_t_test({1, 1, 1}, {2, 2}).p_value == 0.0);
    CHECK_THROWS(welch_t_test({1}, {1, 2}));
}

TEST_CASE("region t-test: regions tile the image, and a brighter region-channel is the one rejected", "[validation][welch]") {
    // the host code of the renderers' region comparison (validation/region_t_test.hpp) on noise images,
    // cheap: noise images instead of renders.
    // 7 x 5 pixels in 3 x 2 regions: the regions' integer bounds do not divide the image evenly.
    lab::validation::UniformRandom rng(5);
    const int width = 7, height = 5, renders = 6;
    auto noise_images = [&](double mean) {
        std::vector<lab::film::ImageRgb> images;
        for (int k = 0; k < renders; ++k) {
            lab::film::ImageRgb image(width, height);
            for (float& v : image.rgb) v = float(mean + 0.1 * normal(rng));
            images.push_back(image);
        }
        return images;
    };
    std::vector<lab::film::ImageRgb> a = noise_images(1.0), b = noise_images(1.0);
    lab::validation::RegionComparison same = lab::validation::compare_by_region(a, b, 3, 2, 0.01);
    REQUIRE(same.regions.size() == 3u * 2u * 3u);
    long area = 0;
    for (const lab::validation::RegionTest& r : same.regions) {
        CHECK((r.x0 >= 0 && r.x0 < r.x1 && r.x1 <= width && r.y0 >= 0 && r.y0 < r.y1 && r.y1 <= height));
        if (r.channel == 0) area += long(r.x1 - r.x0) * (r.y1 - r.y0);
    }
    CHECK(area == width * height);  // every pixel in exactly one region (with the bounds check above)
    CHECK(same.rejected == 0);      // this seed; level 0.01 / 18 per test
    // region (column 2, row 1) = pixels [4, 7) x [2, 5), green 0.5 brighter in b: t about 0.5 / ((0.1 / 3) sqrt(2 / 6)),
    // 26 standard errors of the difference of the means; every other region-channel unchanged
    for (lab::film::ImageRgb& image : b)
        for (int y = 2; y < 5; ++y)
            for (int x = 4; x < 7; ++x) image.pixel(x, y)[1] += 0.5f;
    lab::validation::RegionComparison shifted = lab::validation::compare_by_region(a, b, 3, 2, 0.01);
    const lab::validation::RegionTest* worst = shifted.worst();
    REQUIRE(worst != nullptr);
    CHECK(shifted.rejected == 1);
    CHECK((worst->x0 == 4 && worst->y0 == 2 && worst->channel == 1));
    CHECK_THROWS(lab::validation::compare_by_region({a[0]}, b, 3, 2, 0.01));
    CHECK_THROWS(lab::validation::compare_by_region(a, b, 8, 2, 0.01));
}

TEST_CASE("Student's t critical values invert its tail, and a region's stated power holds on noise images", "[validation][welch]") {
    for (double dof : {1.0, 2.0, 7.5, 30.0, 1e6})
        for (double level : {0.5, 0.05, 3.7e-4}) CHECK(student_t_two_sided(lab::validation::student_t_critical(level, dof), dof) == Approx(level).epsilon(1e-8));
    CHECK(lab::validation::student_t_critical(0.05, 1e7) == Approx(1.959963985).epsilon(1e-6));
    CHECK(lab::validation::student_t_critical(0.5, 1.0) == Approx(1.0).epsilon(1e-9));  // Cauchy: P(|T| >= 1) = 1/2

    // One region of one pixel: 16 renders each with mean 1 and noise 0.1 against the same with the
    // pixel shifted by the detectable difference the red channel's comparison states (averaged over
    // draws); the red channel's test must reject in about 9 of 10 trials (binomial noise on 400
    // trials: 360 +- 6).
    lab::validation::UniformRandom rng(17);
    const int trials = 400, renders = 16;
    auto images = [&](double mean) {
        std::vector<lab::film::ImageRgb> out;
        for (int k = 0; k < renders; ++k) {
            lab::film::ImageRgb image(1, 1);
            for (float& v : image.rgb) v = float(mean + 0.1 * normal(rng));
            out.push_back(image);
        }
        return out;
    };
    int detections = 0;
    double stated = 0.0;
    for (int k = 0; k < trials; ++k) {
        std::vector<lab::film::ImageRgb> reference = images(1.0);
        lab::validation::RegionComparison same = lab::validation::compare_by_region(images(1.0), reference, 1, 1, 0.01);
        // the power the test states from this draw's noise; its expectation is what a trial checks
        stated += lab::validation::detectable_difference(same.regions[0], same.level) / trials;
    }
    for (int k = 0; k < trials; ++k) {
        lab::validation::RegionComparison shifted = lab::validation::compare_by_region(images(1.0 + stated), images(1.0), 1, 1, 0.01);
        detections += shifted.regions[0].result.p_value < shifted.level;
    }
    INFO("stated detectable difference " << stated << ", detected in " << detections << " of " << trials);
    CHECK(detections >= int(0.85 * trials));
    CHECK(detections <= int(0.95 * trials));
}

TEST_CASE("The paired t-test rejects equal means at its level and sees through the noise a pair shares", "[validation][welch]") {
    lab::validation::UniformRandom rng(23);
    const int trials = 2000, n = 8;
    const double alpha = 0.05;
    int false_rejections = 0, paired_detections = 0, welch_detections = 0;
    for (int k = 0; k < trials; ++k) {
        // each pair shares noise of deviation 1 (the same random numbers) and has its own of 0.1
        std::vector<double> a(n), b(n), c(n);
        for (int i = 0; i < n; ++i) {
            double shared = normal(rng);
            a[i] = 1.0 + shared + 0.1 * normal(rng);
            b[i] = 1.0 + shared + 0.1 * normal(rng);
            c[i] = 1.2 + shared + 0.1 * normal(rng);  // 0.2 higher: 4 standard errors of the mean paired difference
        }
        false_rejections += lab::validation::paired_t_test(a, b).p_value < alpha;
        paired_detections += lab::validation::paired_t_test(c, b).p_value < alpha;
        welch_detections += welch_t_test(c, b).p_value < alpha;  // lost in the shared noise
    }
    // Binomial(2000, 0.05): 100 +- 9.7; the paired test is exact for normal differences
    INFO("false rejections " << false_rejections << ", detections: paired " << paired_detections << ", Welch " << welch_detections);
    CHECK(std::abs(false_rejections - 100) <= 39);
    CHECK(paired_detections > trials * 0.8);
    CHECK(welch_detections < trials * 0.2);
    CHECK(lab::validation::paired_t_test({1, 2, 3}, {0, 1, 2}).p_value == 0.0);  // every difference 1: no noise
    CHECK(lab::validation::paired_t_test({1, 2, 3}, {1, 2, 3}).p_value == 1.0);
    CHECK_THROWS(lab::validation::paired_t_test({1, 2, 3}, {1, 2}));
}
