#include "viewer/display_denoiser.hpp"

#include "render/display_denoise.hpp"

namespace lab::viewer {

void DisplayDenoiser::restart() {
    first_hits_ = render::FirstHitAovs();
    guide_samples_ = 0;
    last_ = film::ImageRgb();
    last_samples_ = 0;
}

film::ImageRgb DisplayDenoiser::shown(const render::Renderer& renderer, const film::ImageRgb& raw, bool last, int* shown_samples) {
    const int samples = renderer.samples_per_pixel();
    const Clock::time_point start = Clock::now();
    const double since_last = std::chrono::duration<double>(start - last_run_).count();
    const bool first = last_samples_ == 0;
    const bool due = samples > last_samples_ && (first || last || since_last * kTimeShare >= cost_seconds_ * (1.0 - kTimeShare));
    if (due && renderer.pass_pixels() == 0 && samples > 0 && (guide_samples_ == 0 || (samples >= 2 * guide_samples_ && guide_samples_ < kGuideSamples))) {
        first_hits_ = renderer.first_hit_aovs();
        guide_samples_ = samples;
    }
    if (due && guide_samples_ > 0) {
        last_ = render::denoised(raw, render::denoise_guide(first_hits_, renderer.variance()), renderer);
        last_samples_ = samples;
        last_run_ = Clock::now();
        cost_seconds_ = std::chrono::duration<double>(last_run_ - start).count();
    }
    *shown_samples = last_samples_;
    return last_samples_ > 0 ? last_ : raw;
}

}  // namespace lab::viewer
