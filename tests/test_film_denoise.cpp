// The display denoiser (film/denoise): on synthetic renders whose noise-free image is known, it
// removes noise as much as the a-trous filter's own footprint allows where the surface is one, and
// keeps albedo, normal and depth edges and the background sharp.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "film/denoise.hpp"
#include "single_source/host_vocabulary.hpp"

#include "tests/worst_difference.hpp"

// The pass's single-source functions, for its exponential.
namespace atrous_functions {
using namespace single_source;
#include "film/denoise_atrous.h"
}  // namespace atrous_functions

namespace {

// A synthetic render: per pixel a true radiance, an albedo, a normal and a depth; the "render" adds
// Gaussian noise of standard deviation sigma (the variance of the pixel's mean, as the render core
// estimates it, is sigma^2).
struct Synthetic {
    int size;
    lab::film::ImageRgb truth, noisy;
    lab::film::DenoiseGuide guide;
};

template <class Pixel>
Synthetic make_synthetic(int size, float sigma, uint32_t seed, Pixel pixel) {
    Synthetic s{size, lab::film::ImageRgb(size, size), lab::film::ImageRgb(size, size), {}};
    s.guide.albedo = lab::film::ImageRgb(size, size);
    s.guide.normal = lab::film::ImageRgb(size, size);
    s.guide.depth.assign(size_t(size * size), 0.0f);
    s.guide.variance.assign(size_t(size * size), sigma * sigma);
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float radiance[3], albedo[3], normal[3], depth;
            pixel(x, y, radiance, albedo, normal, &depth);
            const size_t p = size_t(y * size + x);
            s.truth.set(x, y, radiance[0], radiance[1], radiance[2]);
            const float n = depth > 0.0f ? noise(rng) : 0.0f;  // the background is seen without noise
            s.noisy.set(x, y, radiance[0] + n * albedo[0], radiance[1] + n * albedo[1], radiance[2] + n * albedo[2]);
            s.guide.albedo.set(x, y, albedo[0], albedo[1], albedo[2]);
            s.guide.normal.set(x, y, normal[0], normal[1], normal[2]);
            s.guide.depth[p] = depth;
            s.guide.variance[p] = depth > 0.0f ? sigma * sigma * (0.2126f * albedo[0] + 0.7152f * albedo[1] + 0.0722f * albedo[2]) *
                                                     (0.2126f * albedo[0] + 0.7152f * albedo[1] + 0.0722f * albedo[2])
                                               : 0.0f;
        }
    return s;
}

// Root mean square difference of the green channel over the pixels where `inside` holds.
template <class Inside>
double rmse(const lab::film::ImageRgb& a, const lab::film::ImageRgb& b, Inside inside) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (inside(x, y)) {
                sum += std::pow(double(a.at(x, y)[1]) - double(b.at(x, y)[1]), 2.0);
                ++n;
            }
    return std::sqrt(sum / n);
}

// The a-trous filter with its edges switched off is a linear filter: the linear spline [1 2 1] / 4
// dilated by 1, 2, 4, ... and convolved, separable. Noise of variance s^2 comes out of it with
// variance s^2 sum(k^2): the best any edge-stopping weighting can do.
double linear_filter_noise_gain(int passes) {
    std::vector<double> kernel = {1.0};
    for (int i = 0; i < passes; ++i) {
        const int step = 1 << i;
        const double spline[3] = {1.0 / 4, 2.0 / 4, 1.0 / 4};
        std::vector<double> next(kernel.size() + size_t(2 * step), 0.0);
        for (size_t k = 0; k < kernel.size(); ++k)
            for (int t = 0; t < 3; ++t) next[k + size_t(t * step)] += kernel[k] * spline[t];
        kernel = next;
    }
    double sum_sq = 0.0;
    for (double k : kernel) sum_sq += k * k;
    return sum_sq * sum_sq;  // two dimensions
}

constexpr float kUp[3] = {0.0f, 0.0f, 1.0f};

// One flat surface facing the camera: albedo 0.5, radiance 0.4, depth 5.
Synthetic flat_surface(int size, float sigma, uint32_t seed) {
    return make_synthetic(size, sigma, seed, [](int, int, float* radiance, float* albedo, float* normal, float* depth) {
        for (int c = 0; c < 3; ++c) {
            albedo[c] = 0.5f;
            radiance[c] = 0.4f;
            normal[c] = kUp[c];
        }
        *depth = 5.0f;
    });
}

}  // namespace

TEST_CASE("Denoiser: on one flat surface it removes the noise the filter's footprint can", "[denoise]") {
    const int size = 160;
    const float sigma = 0.05f;
    Synthetic s = flat_surface(size, sigma, 1);
    const lab::film::DenoiseOptions options;
    const lab::film::ImageRgb denoised = lab::film::denoise(s.noisy, s.guide, options);
    // Away from the borders (where the footprint is cut), far enough that every pass's taps all
    // land inside: 2^0 + ... + 2^(passes - 1) pixels.
    const int margin = (1 << options.passes) - 1;
    auto centre = [&](int x, int y) { return x >= margin && y >= margin && x < size - margin && y < size - margin; };
    const double raw = rmse(s.noisy, s.truth, centre), filtered = rmse(denoised, s.truth, centre);
    // No weighting of the same taps does better on white noise than the linear filter (its gain
    // is the floor, less a 10 % allowance for the sample's own spread over the centre's pixels,
    // which the filter correlates over its footprint); the luminance weight, exponential in the
    // neighbours' noisy differences, gives up part of it. At least a tenfold cut is asked (the
    // issue's target is half at 4 spp).
    const double floor = std::sqrt(linear_filter_noise_gain(options.passes));
    INFO("raw " << raw << ", denoised " << filtered << ", linear filter's floor " << raw * floor);
    CHECK(filtered >= 0.9 * raw * floor);
    CHECK(filtered <= 0.1 * raw);
}

TEST_CASE("Denoiser: without a variance it estimates each pixel's from the image, and still denoises", "[denoise]") {
    const int size = 160;
    const float sigma = 0.05f;
    Synthetic s = flat_surface(size, sigma, 3);
    s.guide.variance.clear();
    // The illumination's noise is sigma (the render's, divided by the albedo it was multiplied by):
    // its luminance's variance sigma^2. The estimate from 49 pixels (box sums) is unbiased; over the image's
    // 154^2 interior pixels its mean is within 5 % (the windows overlap, so fewer than that many are
    // independent: about 154^2 / 49 windows of relative spread sqrt(2 / 48) = 0.2 give 0.3 %).
    const lab::film::AtrousBuffers b = lab::film::demodulate(s.noisy, s.guide);
    double sum = 0.0;
    int n = 0;
    for (int y = 3; y < size - 3; ++y)
        for (int x = 3; x < size - 3; ++x) {
            sum += b.illumination[size_t(y * size + x)][3];
            ++n;
        }
    const double estimate = sum / n;
    INFO("mean estimated variance " << estimate << " against " << sigma * sigma);
    CHECK(estimate == Approx(double(sigma) * sigma).epsilon(0.05));
    const int margin = (1 << lab::film::DenoiseOptions{}.passes) - 1;
    auto centre = [&](int x, int y) { return x >= margin && y >= margin && x < size - margin && y < size - margin; };
    const lab::film::ImageRgb denoised = lab::film::denoise(s.noisy, s.guide);
    CHECK(rmse(denoised, s.truth, centre) <= 0.1 * rmse(s.noisy, s.truth, centre));
}

TEST_CASE("Denoiser: its own variance estimate spans 7 x 7 pixels", "[denoise]") {
    // One surface whose light steps by delta at x = 80 (and, in a second set of images, at y = 80:
    // the sums along rows and down columns are checked apart): a window of N = 49 pixels of which k see the
    // other side has the expected sample variance sigma^2 + delta^2 k (N - k) / (N (N - 1)), k = 7 m
    // for the m of its seven columns across the step (m = 0 from four columns away). Each m's two
    // columns are pooled over 154 rows and four images per direction: the sigma^2 part's spread over some 176
    // independent windows is sqrt(2 / 48 / 176) = 1.5 %, so 5 % tells a window of another size or
    // place (a radius of 2 moves m = 1 to the sigma^2 alone, a third of it).
    const int size = 160, step_at = 80;
    const float sigma = 0.05f, delta = 0.2f;
    for (bool along_y : {false, true}) {
        // per m: the sum of the estimates and their count
        double sums[4] = {0.0, 0.0, 0.0, 0.0};
        int counts[4] = {0, 0, 0, 0};
        for (uint32_t seed = 4; seed < 8; ++seed) {
            Synthetic s = make_synthetic(size, sigma, seed, [&](int x, int y, float* radiance, float* albedo, float* normal, float* depth) {
                for (int c = 0; c < 3; ++c) {
                    albedo[c] = 0.5f;
                    radiance[c] = 0.5f * ((along_y ? y : x) < step_at ? 1.0f : 1.0f + delta);
                    normal[c] = kUp[c];
                }
                *depth = 5.0f;
            });
            s.guide.variance.clear();
            const lab::film::AtrousBuffers b = lab::film::demodulate(s.noisy, s.guide);
            // the lines (columns, or rows) whose window has m lines across the step: step_at - 4 + m
            // and step_at + 3 - m
            for (int m = 0; m <= 3; ++m)
                for (int line : {step_at - 4 + m, step_at + 3 - m})
                    for (int along = 3; along < size - 3; ++along) {
                        sums[m] += b.illumination[along_y ? size_t(line * size + along) : size_t(along * size + line)][3];
                        ++counts[m];
                    }
        }
        for (int m = 0; m <= 3; ++m) {
            const double k = 7.0 * m, N = 49.0;
            const double expected = double(sigma) * sigma + double(delta) * delta * k * (N - k) / (N * (N - 1.0));
            INFO((along_y ? "rows " : "columns ") << m << " across: mean estimate " << sums[m] / counts[m] << " against " << expected);
            CHECK(sums[m] / counts[m] == Approx(expected).epsilon(0.05));
        }
    }
}

TEST_CASE("Denoiser: albedo, normal and depth edges and the background stay sharp", "[denoise]") {
    // A noise-free image whose variance says it is noisy (sigma 0.2 of the illumination): the
    // luminance weight then lets steps of one sigma through, so whatever moves a pixel is the filter
    // mixing across an edge that only the guides (and the demodulation by albedo) can stop.
    const int size = 96;
    const float sigma = 0.2f;
    // Four quadrants: top left | top right differ in albedo only (0.3 | 0.9, the same light: one
    // flat illumination); top left | bottom left in normal (up | +x) with the light one sigma apart;
    // bottom left | bottom right in depth (5 | 20, the same normal), the light one sigma apart again;
    // a strip of background (the sky, seen directly) at x = 0..3.
    Synthetic s = make_synthetic(size, 0.0f, 2, [&](int x, int y, float* radiance, float* albedo, float* normal, float* depth) {
        const bool right = x >= size / 2, bottom = y >= size / 2;
        const float a = !bottom && right ? 0.9f : 0.3f;
        const float light = !bottom ? 1.0f : (right ? 1.4f : 1.2f);
        for (int c = 0; c < 3; ++c) {
            normal[c] = bottom ? (c == 0 ? 1.0f : 0.0f) : kUp[c];
            albedo[c] = a;
            radiance[c] = a * light;
        }
        *depth = bottom && right ? 20.0f : 5.0f;
        if (x < 4) {
            *depth = 0.0f;
            for (int c = 0; c < 3; ++c) {
                radiance[c] = 0.7f;
                albedo[c] = 0.0f;
            }
        }
    });
    for (size_t p = 0; p < s.guide.variance.size(); ++p)
        if (s.guide.depth[p] > 0.0f) s.guide.variance[p] = sigma * sigma * s.guide.albedo.rgb[3 * p] * s.guide.albedo.rgb[3 * p];
    const lab::film::ImageRgb denoised = lab::film::denoise(s.noisy, s.guide);
    // Each pixel is its own side's truth to 1e-3 of the illumination. Across the normal edge the
    // weight is 0 (normals at right angles). Across the depth edge the largest weight is seen from
    // the far side at the widest pass: exp(-|5 - 20| / (sigma_depth 20 step / 96)) = exp(-4.5) at
    // step 8, exp(-9) at step 4. There the three taps across the edge hold 1/4 of the spline's
    // weight against 3/4 on the pixel's own side (weight 1: noise-free, one depth and normal), and
    // the light's step of 0.2 has a luminance weight of exp(-0.2 / (4 x 0.2)) = 0.78, so the pass
    // moves the pixel by at most 0.2 x 0.78 exp(-4.5) (1/4) / (3/4) = 6e-4; float rounding is 1e-6.
    // Mixing across any edge moves the pixels beside it by about half its step, 0.1 to 0.3.
    auto check_band = [&](const char* edge, int x0, int x1, int y0, int y1) {
        double worst = 0.0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                worst = worse_of(worst, double(std::fabs(denoised.at(x, y)[1] - s.truth.at(x, y)[1])) / s.guide.albedo.at(x, y)[1]);
        INFO(edge << ": largest illumination error beside it " << worst);
        CHECK(worst <= 1e-3);
    };
    check_band("albedo edge", size / 2 - 2, size / 2 + 2, 4, size / 2);
    check_band("normal edge", 4, size / 2, size / 2 - 2, size / 2 + 2);
    check_band("depth edge", size / 2 - 2, size / 2 + 2, size / 2, size);
    // The background is left exactly as it was.
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < 4; ++x) REQUIRE(denoised.at(x, y) == s.noisy.at(x, y));
}

TEST_CASE("Denoiser: its weights' exponential is e^-x to its series' remainder", "[denoise]") {
    // e^-x = 2^-n e^f with |f| <= ln(2) / 2, and e^f's series stops at f^4: the remainder is at
    // most |f|^5 / 5! e^|f|, against e^f >= e^-|f|: a relative (ln(2) / 2)^5 / 120 x 2 = 8.4e-5 (a
    // series one power shorter: 6e-4), and float rounding, a few 1e-7.
    const double bound = std::pow(0.5 * std::log(2.0), 5.0) / 120.0 * 2.0 + 1e-6;
    double worst = 0.0;
    for (double x = -0.3; x < 86.5; x += 1e-3) {
        const double exact = std::exp(-double(float(x)));
        worst = worse_of(worst, std::fabs(double(atrous_functions::atrous_exp_neg(float(x))) - exact) / exact);
    }
    INFO("largest relative error " << worst << " against " << bound);
    CHECK(worst <= bound);
    // Past e^-86.6 = 2^-125 the weight stays there: 0 beside any other tap's.
    CHECK(atrous_functions::atrous_exp_neg(1000.0f) == Approx(std::ldexp(1.0, -125)).epsilon(bound));
    CHECK(atrous_functions::atrous_exp_neg(INFINITY) == Approx(std::ldexp(1.0, -125)).epsilon(bound));
}

TEST_CASE("Denoiser: a guide of another size is refused", "[denoise]") {
    lab::film::ImageRgb image(8, 8);
    lab::film::DenoiseGuide guide;
    guide.albedo = lab::film::ImageRgb(8, 8);
    guide.normal = lab::film::ImageRgb(8, 7);
    guide.depth.assign(64, 1.0f);
    guide.variance.assign(64, 0.0f);
    CHECK_THROWS_AS(lab::film::denoise(image, guide), std::invalid_argument);
}
