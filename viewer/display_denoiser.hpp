// What the viewer's render worker publishes when the display is denoised (render/display_denoise):
// the film accumulates unfiltered, and the image shown is filtered from it now and then. On a CPU
// the filter costs about as much as a sample of every pixel, so it runs at most a share of the
// worker's time: when the render has new samples and the time since the last filter is at least
// its cost x (1 - share) / share; in between, the last denoised image of the state stays shown.
// Its guide is the film's variance of each pixel's mean, read at each filter, and the first-hit
// AOVs, taken when a pass is complete (Renderer::first_hit_aovs reads whole passes) at 1, 2 and 4
// samples per pixel, so that their edges are antialiased, and then kept (as the views' are: a pass
// of 16 samples would hold up the next change by a fraction of a second).
#pragma once

#include <chrono>

#include "film/denoise.hpp"
#include "film/image.hpp"
#include "render/renderer.hpp"

namespace lab::viewer {

class DisplayDenoiser {
public:
    // At most this share of the worker's time goes to the filter and its guide.
    static constexpr double kTimeShare = 0.15;
    // The guide is taken again until it holds this many samples per pixel.
    static constexpr int kGuideSamples = 4;

    // A new state or size: the guide and the last denoised image are of the old one.
    void restart();
    // The image to show for `raw`, the renderer's current full-size mean: the denoised one when the
    // filter runs now, else the last denoised image of this state, else `raw` (no guide yet: the
    // first pass is not complete). *shown_samples: the samples per pixel the denoised image shown
    // was filtered from (0 when `raw` is shown). `last`: the render has stopped, so what it holds is
    // filtered now, whatever the time share. Throws what the renderer's filter throws.
    film::ImageRgb shown(const render::Renderer& renderer, const film::ImageRgb& raw, bool last, int* shown_samples);

private:
    using Clock = std::chrono::steady_clock;
    render::FirstHitAovs first_hits_;  // the guide's; the variance is the film's at each filter
    int guide_samples_ = 0;
    film::ImageRgb last_;
    int last_samples_ = 0;
    double cost_seconds_ = 0.0;  // the last filter's, with the guide taken for it
    Clock::time_point last_run_{};
};

}  // namespace lab::viewer
