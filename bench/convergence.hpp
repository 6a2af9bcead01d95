// What the render benches share: a long reference render whose own noise is measured from its two
// halves, and equal-time runs of several renderers against it (RMSE after every launch), for the
// speed-against-accuracy tables and charts. Figures, not timed tests: ratios within one run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "film/image.hpp"
#include "plots/speed_accuracy_chart.hpp"
#include "render/renderer.hpp"

namespace lab::cli {

// Makes a fresh renderer for a render input (on the bench's device).
using RendererFactory = std::function<std::unique_ptr<render::Renderer>(const render::RenderInput&)>;

// Adds samples for `seconds` in launches short enough to chart (about 40 per run); calls
// `checkpoint(elapsed)` after each launch.
void render_for(render::Renderer& renderer, double seconds, const std::function<void(double)>& checkpoint);

struct Reference {
    film::ImageRgb image;
    double noise = 0.0;  // the reference's own RMSE, from its two halves
    int samples_per_pixel = 0;
    render::RenderStatistics half_stats;  // one half's statistics: throughput figures
};

// Two renders of `input` with other seeds for seconds / 2 each, averaged.
Reference render_reference(const RendererFactory& make, render::RenderInput input, double seconds);

struct EqualTimeRun {
    std::string name;
    render::RenderInput input;
};

struct EqualTimeResult {
    plots::ConvergenceSeries series;
    render::RenderStatistics stats;
    double final_rmse() const { return series.rmse.empty() ? 0.0 : series.rmse.back(); }
};

// Each run for `seconds`, its RMSE against the reference after every launch; prints a table row each.
std::vector<EqualTimeResult> run_equal_time(const RendererFactory& make, const std::vector<EqualTimeRun>& runs, const Reference& reference,
                                            double seconds);

}  // namespace lab::cli
