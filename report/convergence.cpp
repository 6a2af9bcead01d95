#include "report/convergence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/seconds_since.hpp"
#include "film/image_stats.hpp"

namespace lab::report {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

double image_error_value(const film::ImageRgb& image, const film::ImageRgb& reference, ErrorMetric metric) {
    const film::ImageError e = film::image_error(image, reference);
    return metric == ErrorMetric::rmse ? e.rmse_mean : e.relative_rmse_mean;
}

void render_for(render::Renderer& renderer, double seconds, const std::function<void(double)>& checkpoint) {
    Clock::time_point start = Clock::now();
    while (seconds_since(start) < seconds) {
        Clock::time_point launch = Clock::now();
        renderer.add_samples(renderer.samples_per_launch());
        double took = seconds_since(launch);
        checkpoint(seconds_since(start));
        // double the launch while it is short, but keep ~20 points per series
        if (took < seconds / 40.0) renderer.set_samples_per_launch(renderer.samples_per_launch() * 2);
    }
}

namespace {

// The mean of two renders with other seeds, and its own noise from their difference.
Reference reference_from_halves(const render::Renderer& half_a, const render::Renderer& half_b) {
    film::ImageRgb a = half_a.image(), b = half_b.image();
    Reference r;
    r.image = film::ImageRgb(a.width, a.height);
    for (size_t k = 0; k < a.rgb.size(); ++k) r.image.rgb[k] = 0.5f * (a.rgb[k] + b.rgb[k]);
    // RMSE(a, b) = sqrt(2) sigma_half, and the mean of the halves has sigma_half / sqrt(2).
    const film::ImageError halves = film::image_error(a, b);
    r.noise = halves.rmse_mean / 2.0;
    r.relative_noise = halves.relative_rmse_mean / 2.0;
    r.half_stats = half_a.statistics();
    r.samples_per_pixel = r.half_stats.samples_per_pixel + half_b.statistics().samples_per_pixel;
    return r;
}

// The halves' inputs: seeds no run of the benches uses.
render::RenderInput half_input(render::RenderInput input, int half) {
    input.settings.seed += 1000003 + unsigned(half);
    return input;
}

}  // namespace

Reference render_reference(const RendererFactory& make, render::RenderInput input, double seconds) {
    std::unique_ptr<render::Renderer> half_a = make(half_input(input, 0));
    std::unique_ptr<render::Renderer> half_b = make(half_input(input, 1));
    render_for(*half_a, seconds / 2, [](double) {});
    render_for(*half_b, seconds / 2, [](double) {});
    return reference_from_halves(*half_a, *half_b);
}

Reference render_reference_samples(const RendererFactory& make, const render::RenderInput& input, int samples_per_pixel) {
    std::unique_ptr<render::Renderer> half_a = make(half_input(input, 0));
    std::unique_ptr<render::Renderer> half_b = make(half_input(input, 1));
    for (render::Renderer* half : {half_a.get(), half_b.get()}) {
        half->set_samples_per_launch(std::max(1, std::min(samples_per_pixel / 2, 16)));
        half->add_samples(samples_per_pixel / 2);
    }
    return reference_from_halves(*half_a, *half_b);
}

std::vector<EqualTimeResult> run_equal_time(const RendererFactory& make, const std::vector<EqualTimeRun>& runs, const Reference& reference,
                                            double seconds, ErrorMetric metric) {
    std::vector<EqualTimeResult> results;
    std::printf("equal time, %.1f s each:\n  %-16s %8s %12s %12s %14s\n", seconds, "run", "spp", "paths/s", metric == ErrorMetric::rmse ? "RMSE" : "rel. RMSE",
                metric == ErrorMetric::rmse ? "RMSE x sqrt(t)" : "rel. x sqrt(t)");
    for (const EqualTimeRun& run : runs) {
        std::unique_ptr<render::Renderer> renderer = make(run.input);
        // one sample first, not timed: PoCL compiles the kernel for its work-group size at the first launch
        renderer->add_samples(1);
        renderer->reset();
        EqualTimeResult r;
        r.series.name = run.name;
        render_for(*renderer, seconds, [&](double t) {
            r.series.seconds.push_back(t);
            r.series.rmse.push_back(image_error_value(renderer->image(), reference.image, metric));
        });
        r.stats = renderer->statistics();
        std::printf("  %-16s %8d %12.3g %12.4g %14.4g\n", run.name.c_str(), r.stats.samples_per_pixel, r.stats.paths_per_second(),
                    r.final_rmse(), r.final_rmse() * std::sqrt(r.series.seconds.back()));
        std::fflush(stdout);
        results.push_back(std::move(r));
    }
    return results;
}

PairedError paired_relative_error(const film::ImageRgb& a1, const film::ImageRgb& a2, const film::ImageRgb& b1, const film::ImageRgb& b2) {
    for (const film::ImageRgb* image : {&a2, &b1, &b2})
        if (image->width != a1.width || image->height != a1.height || image->rgb.size() != a1.rgb.size())
            throw std::invalid_argument("paired error: images of different sizes");
    const size_t pixels = a1.pixel_count();
    PairedError e;
    if (pixels == 0) return e;
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0, sum_squares = 0.0, baseline = 0.0;
        for (size_t k = 0; k < pixels; ++k) {
            const size_t i = 3 * k + size_t(c);
            const double product = double(a1.rgb[i] - b1.rgb[i]) * double(a2.rgb[i] - b2.rgb[i]);
            sum += product;
            sum_squares += product * product;
            baseline += 0.5 * (double(b1.rgb[i]) + double(b2.rgb[i]));
        }
        const double n = double(pixels);
        const double mean = sum / n, mean_of_baseline = baseline / n;
        const double variance = pixels > 1 ? std::max(0.0, (sum_squares - n * mean * mean) / (n - 1.0)) : 0.0;
        const double standard_error = std::sqrt(variance / n);
        if (mean_of_baseline > 0.0) {
            e.relative += std::sqrt(std::max(0.0, mean)) / mean_of_baseline / 3.0;
            e.noise += std::sqrt(2.0 * standard_error) / mean_of_baseline / 3.0;
        }
    }
    return e;
}

}  // namespace lab::report
