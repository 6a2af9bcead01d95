// Speed against accuracy, as the render benches and the report measure it: a long reference render
// whose own noise is measured from its two halves, and equal-time runs of several renderers against
// it (the error after every launch), for the speed-against-accuracy tables and charts. Figures, not
// timed tests: ratios within one run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "film/image.hpp"
#include "plots/speed_accuracy_chart.hpp"
#include "render/renderer.hpp"

namespace lab::report {

// Makes a fresh renderer for a render input (on the bench's device).
using RendererFactory = std::function<std::unique_ptr<render::Renderer>(const render::RenderInput&)>;

// Adds samples for `seconds` in launches short enough to chart (about 40 per run); calls
// `checkpoint(elapsed)` after each launch.
void render_for(render::Renderer& renderer, double seconds, const std::function<void(double)>& checkpoint);

// How a run's image is compared with the reference: the RMSE (the mean of the three channels'), or
// the relative RMSE (each channel's RMSE over the reference's mean in that channel, averaged), which
// compares scenes of different brightness.
enum class ErrorMetric { rmse, relative_rmse };

double image_error_value(const film::ImageRgb& image, const film::ImageRgb& reference, ErrorMetric metric);

struct Reference {
    film::ImageRgb image;
    double noise = 0.0;           // the reference's own RMSE, from its two halves
    double relative_noise = 0.0;  // the same as a relative RMSE
    int samples_per_pixel = 0;
    render::RenderStatistics half_stats;  // one half's statistics: throughput figures
};

// Two renders of `input` with other seeds for seconds / 2 each, averaged.
Reference render_reference(const RendererFactory& make, render::RenderInput input, double seconds);
// The same from two renders of samples_per_pixel / 2 samples each (at least 2 in all).
Reference render_reference_samples(const RendererFactory& make, const render::RenderInput& input, int samples_per_pixel);

struct EqualTimeRun {
    std::string name;
    render::RenderInput input;
};

struct EqualTimeResult {
    plots::ConvergenceSeries series;
    render::RenderStatistics stats;
    double final_rmse() const { return series.rmse.empty() ? 0.0 : series.rmse.back(); }
};

// Each run for `seconds`, its error against the reference after every launch (series.rmse holds the
// metric's values); prints a table row each.
std::vector<EqualTimeResult> run_equal_time(const RendererFactory& make, const std::vector<EqualTimeRun>& runs, const Reference& reference,
                                            double seconds, ErrorMetric metric = ErrorMetric::rmse);

// The error a change of settings causes, measured from renders that share their random numbers:
// the setting's halves a1, a2 and the baseline's b1, b2, half 1 of both drawn with one seed, half 2
// with another. Per pixel and channel, (a1 - b1)(a2 - b2) has the expectation bias^2 whatever the
// noise, since the two halves are independent; and the shared numbers keep its variance small, as
// both renders follow nearly the same paths.
struct PairedError {
    double relative = 0.0;  // per channel sqrt(max(0, the product's mean over pixels)) over the baseline's mean, averaged
    double noise = 0.0;     // the same of twice the product mean's standard error: a smaller error is not told from noise
};

// Throws std::invalid_argument for images of different sizes.
PairedError paired_relative_error(const film::ImageRgb& a1, const film::ImageRgb& a2, const film::ImageRgb& b1, const film::ImageRgb& b2);

}  // namespace lab::report
