// The film's variance estimate (kernels/film.h squares, render::resolve_variance) and its sample
// count (render::finite_sample_counts), against what they claim.
//
// Variance against the spread over seeds. K renders of n samples per pixel under independent seeds
// give each pixel K means m_k and K variance estimates v_k = s_k^2 / n. The ratio of the spread of
// the means, S^2 = sum (m_k - mean m)^2 / (K - 1), to the mean estimate V = mean v_k is one-way
// ANOVA's F statistic (between-seed over within-seed mean square, both divided by n): for normal
// samples F ~ F(d1, d2), d1 = K - 1, d2 = K (n - 1), with mean d2 / (d2 - 2) and variance
// 2 d2^2 (d1 + d2 - 2) / (d1 (d2 - 2)^2 (d2 - 4)) (each a chi-square over its degrees of freedom).
// Pixels are independent (their own random streams), so the mean of F over P pixels lies within
// 4 sqrt(variance / P) of its mean but for a chance of 6e-5. A variance of the samples instead of
// the mean's (off by the factor n) gives a mean F near 1 / n, one over n n-fold: both are checked
// to fall outside. The scene is the test model on its ground under a white sky: paths bounce
// between the ball and the ground, so a pixel's radiance spreads over a range rather than a few
// values (a lone Lambert sphere's paths are all its albedo, or the sky: a two-valued mixture on
// its edge, far from normal at 16 samples). Pixels without spread -- the sky's (every sample the
// sky), or a variance at the float sums' rounding floor (under 1e-6 of the squared mean; a
// relative standard error of 0.1 % is far below what 16 samples resolve) -- are left out.
//
// With splats (BDPT on scenes/caustic.json, whose focused light under the glass ball reaches the
// camera almost only by the light tracer's t = 1 splats): a pixel's value is its own samples plus
// what other pixels' light paths splatted onto it, and its variance is squared per pass
// (render::add_pass_squares). Its spread there is far from normal (rare bright splats), so the
// check is on sums, which need no normality: per pixel the spread of the seeds' means S^2 and the
// mean estimate V are both unbiased for the variance of the mean, so D = S^2 - V has mean 0, and
// the mean of D over P pixels lies within 4 of its standard errors (the pixels' spread of D over
// sqrt P) but for a chance of 6e-5. The film squared per sample, without the splats, fails it
// (shown once by turning the per-pass squares off: the mean of D was then 4.8 standard errors out,
// against 0.7 with them). On OpenCL, where it runs in 2 s; the host build squares its passes with
// the same code (Renderer::add_samples) and gives the same variance (test_render_host_device.cpp).
//
// Merge: two parts of a render over disjoint samples, merged as `dtoadq merge` does
// (merge_film_files), give the whole render's variance to the float rounding of the sums' order:
// a float sum of n terms in another order differs by at most 2 n eps of the sum of their
// magnitudes, so sum x^2 by 2 n eps sum x^2 and (sum x)^2 / n by 4 n eps (sum x)^2 / n, and the
// variance of the mean (sum x^2 - (sum x)^2 / n) / ((n - 1) n) by at most
// 6 n eps (sum x^2 + (sum x)^2 / n) / ((n - 1) n). A merge that leaves the second part's squares
// out is checked to fail.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "opencl/runtime.hpp"
#include "render/aov_layers.hpp"
#include "render/film_file.hpp"
#include "render/film_resolve.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"

namespace {

constexpr int kSize = 20, kSeeds = 8, kSpp = 16;

lab::render::RenderInput test_model(uint64_t seed, lab::render::Integrator integrator) {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:1,1,1", kSize, lab::render::LightSampling::bsdf, seed);
    input.settings.integrator = integrator;
    return input;
}

// One seed's render: per pixel the mean of its own samples (the path tracer's film, squared per
// sample) and the variance estimate, green channel.
struct SeedRender {
    std::vector<double> mean, variance;
};

template <class MakeRenderer>
SeedRender render_seed(MakeRenderer make, uint64_t seed) {
    auto renderer = make(seed);
    renderer->set_samples_per_launch(kSpp);
    renderer->add_samples(kSpp);
    const lab::render::FilmReadback film = renderer->film();
    const lab::film::ImageRgb variance = lab::render::resolve_variance(film, kSpp, kSize, kSize);
    SeedRender r;
    for (int p = 0; p < kSize * kSize; ++p) {
        r.mean.push_back(double(film.accumulation[4 * size_t(p) + 1]) / double(kSpp - film.accumulation[4 * size_t(p) + 3]));
        r.variance.push_back(double(variance.rgb[3 * size_t(p) + 1]));
    }
    return r;
}

struct FSummary {
    int pixels = 0;
    double mean_f = 0.0;  // the mean over pixels of S^2 / (scale V)
};

FSummary mean_f(const std::vector<SeedRender>& seeds, double scale) {
    FSummary f;
    double sum = 0.0;
    for (size_t p = 0; p < seeds.front().mean.size(); ++p) {
        double m = 0.0, v = 0.0;
        for (const SeedRender& s : seeds) {
            m += s.mean[p] / double(seeds.size());
            v += s.variance[p] / double(seeds.size());
        }
        if (!(v > 1e-6 * m * m)) continue;  // no spread: the sky, or a float sum's rounding
        double spread = 0.0;
        for (const SeedRender& s : seeds) spread += (s.mean[p] - m) * (s.mean[p] - m) / double(seeds.size() - 1);
        sum += spread / (scale * v);
        ++f.pixels;
    }
    f.mean_f = sum / double(f.pixels);
    return f;
}

template <class MakeRenderer>
void check_variance_against_seeds(MakeRenderer make) {
    std::vector<SeedRender> seeds;
    for (int k = 0; k < kSeeds; ++k) seeds.push_back(render_seed(make, 1000 + uint64_t(k)));
    const double d1 = kSeeds - 1, d2 = double(kSeeds) * (kSpp - 1);
    const double expected = d2 / (d2 - 2.0);
    const double var_f = 2.0 * d2 * d2 * (d1 + d2 - 2.0) / (d1 * (d2 - 2.0) * (d2 - 2.0) * (d2 - 4.0));
    const FSummary f = mean_f(seeds, 1.0);
    const double half_width = 4.0 * std::sqrt(var_f / double(f.pixels));
    const FSummary per_sample = mean_f(seeds, double(kSpp)), over_n = mean_f(seeds, 1.0 / double(kSpp));
    INFO("mean F over " << f.pixels << " pixels " << f.mean_f << ", expected " << expected << " +- " << half_width
                        << "; with the samples' variance (x n) " << per_sample.mean_f << ", with the mean's over n " << over_n.mean_f);
    CHECK(f.pixels > kSize * kSize / 2);
    CHECK(std::abs(f.mean_f - expected) <= half_width);
    CHECK(std::abs(per_sample.mean_f - expected) > half_width);  // the check fails on a variance off by n
    CHECK(std::abs(over_n.mean_f - expected) > half_width);
}

// The bound on |a - b| of two variances of the mean from the same n samples summed in another order.
double reordered_variance_bound(double sum, double squares, double n) {
    const double eps = std::ldexp(1.0, -24);
    return 6.0 * n * eps * (std::abs(squares) + sum * sum / n) / ((n - 1.0) * n);
}

lab::render::FilmFile part_file(const char* path, int first, int end) {
    lab::render::HostRenderer renderer(test_model(7, lab::render::Integrator::pt), 2);
    renderer.set_first_sample(first);
    renderer.set_samples_per_launch(end - first);
    renderer.add_samples(end - first);
    lab::render::FilmFile f;
    f.path = path;
    f.width = f.height = kSize;
    f.film = renderer.film();
    f.ranges = renderer.sample_ranges();
    return f;
}

// Pixels whose merged variance differs from the whole render's by more than the reordering bound.
int pixels_off(const lab::render::FilmFile& merged, const lab::render::FilmReadback& whole, int spp) {
    const lab::film::ImageRgb a = lab::render::resolve_variance(merged.film, spp, kSize, kSize);
    const lab::film::ImageRgb b = lab::render::resolve_variance(whole, spp, kSize, kSize);
    int off = 0;
    for (size_t p = 0; p < a.pixel_count(); ++p)
        for (size_t c = 0; c < 3; ++c) {
            const double bound = reordered_variance_bound(whole.accumulation[4 * p + c], whole.squares[4 * p + c], spp);
            if (!(std::abs(double(a.rgb[3 * p + c]) - double(b.rgb[3 * p + c])) <= bound)) ++off;
        }
    return off;
}

// The caustic's check: many seeds of few samples, for the power to see a variance that leaves the
// splats out (the spread of K means has K - 1 degrees of freedom; the estimate pools K (n - 1)).
constexpr int kSplatSeeds = 32, kSplatSpp = 4;

// The caustic under BDPT, `seed`'s render of kSplatSpp passes of one sample: per pixel the mean
// with its splats and the variance estimate, green channel.
template <class MakeRenderer>
SeedRender render_splatting_seed(MakeRenderer make, uint64_t seed) {
    auto renderer = make(seed);
    renderer->set_samples_per_launch(1);
    renderer->add_samples(kSplatSpp);
    const lab::film::ImageRgb image = renderer->image(), variance = renderer->variance();
    SeedRender r;
    for (size_t p = 0; p < image.pixel_count(); ++p) {
        r.mean.push_back(double(image.rgb[3 * p + 1]));
        r.variance.push_back(double(variance.rgb[3 * p + 1]));
    }
    return r;
}

lab::render::RenderInput caustic(uint64_t seed) {
    lab::render::RenderInput input;
    input.scene = lab::scene::apply_options(lab::scene::load_scene("scenes/caustic.json"), lab::scene::CompileOptions{});
    input.settings.width = input.settings.height = kSize;
    input.settings.seed = seed;
    input.settings.integrator = lab::render::Integrator::bdpt;
    return input;
}

// The mean of D = S^2 - V over the pixels, in its standard errors.
template <class MakeRenderer>
void check_splatting_variance_against_seeds(MakeRenderer make) {
    std::vector<SeedRender> seeds;
    for (int k = 0; k < kSplatSeeds; ++k) seeds.push_back(render_splatting_seed(make, 2000 + uint64_t(k)));
    std::vector<double> d;
    double spread_sum = 0.0, estimate_sum = 0.0;
    for (size_t p = 0; p < seeds.front().mean.size(); ++p) {
        double m = 0.0, v = 0.0, spread = 0.0;
        for (const SeedRender& s : seeds) {
            m += s.mean[p] / double(kSplatSeeds);
            v += s.variance[p] / double(kSplatSeeds);
        }
        for (const SeedRender& s : seeds) spread += (s.mean[p] - m) * (s.mean[p] - m) / double(kSplatSeeds - 1);
        REQUIRE(std::isfinite(v));
        d.push_back(spread - v);
        spread_sum += spread;
        estimate_sum += v;
    }
    double mean_d = 0.0, var_d = 0.0;
    for (double x : d) mean_d += x / double(d.size());
    for (double x : d) var_d += (x - mean_d) * (x - mean_d) / double(d.size() - 1);
    const double standard_error = std::sqrt(var_d / double(d.size()));
    INFO("sum over pixels: spread of the seeds' means " << spread_sum << ", variance estimate " << estimate_sum << "; mean D " << mean_d
                                                          << " = " << mean_d / standard_error << " standard errors");
    CHECK(spread_sum > 0.0);
    CHECK(std::abs(mean_d) <= 4.0 * standard_error);
}

}  // namespace

TEST_CASE("Variance of the pixel mean: BDPT's covers its splats (caustic, OpenCL)", "[render][aov][variance][opencl]") {
    lab::opencl::Runtime runtime("");
    check_splatting_variance_against_seeds([&runtime](uint64_t seed) {
        return std::make_unique<lab::render::OpenClRenderer>(runtime, caustic(seed));
    });
}

TEST_CASE("Variance of the pixel mean: agrees with the spread over seeds (path tracer, host)", "[render][aov][variance]") {
    check_variance_against_seeds([](uint64_t seed) {
        return std::make_unique<lab::render::HostRenderer>(test_model(seed, lab::render::Integrator::pt), 2);
    });
}

TEST_CASE("Variance of the pixel mean: agrees with the spread over seeds (path tracer, OpenCL)", "[render][aov][variance][opencl]") {
    lab::opencl::Runtime runtime("");
    check_variance_against_seeds([&runtime](uint64_t seed) {
        return std::make_unique<lab::render::OpenClRenderer>(runtime, test_model(seed, lab::render::Integrator::pt));
    });
}

TEST_CASE("Variance of the pixel mean: two merged parts give the whole render's", "[render][aov][variance][film-file]") {
    const lab::render::FilmFile a = part_file("a.exr", 0, 6), b = part_file("b.exr", 6, 16);
    const lab::render::FilmFile whole = part_file("whole.exr", 0, 16);
    const lab::render::FilmFile merged = lab::render::merge_film_files({a, b});
    CHECK(merged.ranges.count() == 16);
    CHECK(pixels_off(merged, whole.film, 16) == 0);
    lab::render::FilmFile first_squares_only = merged;  // a merge that drops the second part's squares
    first_squares_only.film.squares = a.film.squares;
    CHECK(pixels_off(first_squares_only, whole.film, 16) > kSize * kSize / 2);
}

TEST_CASE("Sample count AOV: every pixel holds the spp, less its non-finite samples", "[render][aov]") {
    lab::render::HostRenderer renderer(test_model(3, lab::render::Integrator::pt), 2);
    renderer.set_samples_per_launch(5);
    renderer.add_samples(5);
    lab::render::FilmReadback film = renderer.film();
    lab::render::AovSelection selection;
    selection.samples = selection.variance = true;
    auto count_not = [&](const lab::render::FilmReadback& f, float spp) {
        const std::vector<lab::film::ImageChannel> channels = lab::render::aov_channels(nullptr, f, 5, kSize, kSize, selection);
        REQUIRE(channels.size() == 4);
        REQUIRE(channels[3].name == "samples.X");
        int off = 0;
        for (float v : channels[3].values) off += v != spp;
        return off;
    };
    CHECK(count_not(film, 5.0f) == 0);
    film.accumulation[3] = 1.0f;  // pixel 0 had a non-finite sample: 4 in its mean
    CHECK(count_not(film, 5.0f) == 1);
}
