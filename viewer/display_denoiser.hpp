// What the viewer's render worker publishes when the display is denoised (render/display_denoise):
// the film accumulates unfiltered, and the image shown is filtered from it now and then, on a
// thread of its own (render/display_filter.hpp), so that the worker never waits for the filter: a
// change is rendered and shown raw at once, while a filter of the old state still running is
// cancelled at its next pass and its image dropped. On a CPU the filter costs about as much as a
// sample of every pixel, so it runs at most a share of the time: the worker hands it the latest
// image when the render has new samples, the filter is idle, and the time since the last filter
// ended is at least its cost x (1 - share) / share; in between, the last denoised image of the state
// stays shown, and until the first one of a state is ready the raw image is.
// Its guide is the film's variance of each pixel's mean, read when the image is handed over, and
// the first-hit AOVs, taken when a pass is complete (Renderer::first_hit_aovs reads whole passes)
// at 1, 2 and 4 samples per pixel, so that their edges are antialiased, and then kept. Their march
// costs about half a sample of every pixel and runs on the worker (it needs the renderer), in
// pieces between which a newer state ends it: a change waits at most one piece.
// DTOADQ_DEBUG_STALL_DENOISER=1 in the environment makes the filter's thread stop at its first
// image until the viewer closes (it says so on stderr): a test that a change never waits for it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "film/denoise.hpp"
#include "film/image.hpp"
#include "render/display_filter.hpp"
#include "render/renderer.hpp"

namespace lab::viewer {

class DisplayDenoiser {
public:
    // At most this share of the time goes to the filter.
    static constexpr double kTimeShare = 0.15;
    // The guide is taken again until it holds this many samples per pixel.
    static constexpr int kGuideSamples = 4;

    // Starts the filter's thread. `on_filtered` is called on it when a denoised image is ready, for
    // the worker to publish it (it may be sleeping, rendered out).
    DisplayDenoiser(std::unique_ptr<render::DisplayFilter> filter, std::function<void()> on_filtered);
    ~DisplayDenoiser();
    DisplayDenoiser(const DisplayDenoiser&) = delete;
    DisplayDenoiser& operator=(const DisplayDenoiser&) = delete;

    // A new state or size: the guide and the last denoised image are of the old one, and so is
    // what the filter runs on (cancelled, dropped). Never waits for the filter.
    void restart();
    // The image to show for `raw`, the renderer's current full-size mean: the last denoised image
    // of this state, else `raw`; hands `raw` to the filter when it is due. *shown_samples: the
    // samples per pixel the denoised image shown was filtered from (0 when `raw` is shown). `last`:
    // the render has stopped, so what it holds is filtered as soon as the filter is idle, whatever
    // the time share. Never waits for the filter; throws what the filter threw (on its thread)
    // since the last call, or what the renderer throws for the guide. The guide's march runs here,
    // in pieces (Renderer::first_hit_aovs), and is given up when `changed` says a newer state waits.
    film::ImageRgb shown(const render::Renderer& renderer, const film::ImageRgb& raw, bool last, const std::function<bool()>& changed,
                         int* shown_samples);

private:
    using Clock = std::chrono::steady_clock;
    struct Job {
        film::ImageRgb raw;
        film::DenoiseGuide guide;
        int samples = 0;
        uint64_t epoch = 0;
    };
    void run();  // the filter's thread

    std::unique_ptr<render::DisplayFilter> filter_;
    std::function<void()> on_filtered_;
    const bool stall_;  // DTOADQ_DEBUG_STALL_DENOISER

    // The worker's side.
    render::FirstHitAovs first_hits_;  // the guide's; the variance is the film's at each handover
    int guide_samples_ = 0;
    film::ImageRgb last_;
    int last_samples_ = 0;       // of last_
    int requested_samples_ = 0;  // of the last image handed over in this state
    double cost_seconds_ = 0.0;  // the last filter's, on its thread
    Clock::time_point last_run_{};  // when it ended

    // Shared with the filter's thread, under mutex_.
    std::mutex mutex_;
    std::condition_variable wake_;
    std::atomic<uint64_t> epoch_{0};  // counts restarts; read unlocked by the filter to cancel
    std::optional<Job> job_;          // handed over, not yet taken
    bool running_ = false, stop_ = false;
    film::ImageRgb result_;
    int result_samples_ = 0;
    uint64_t result_epoch_ = 0;
    double result_cost_ = 0.0;
    Clock::time_point result_end_{};
    std::string error_;
    std::thread thread_;
};

}  // namespace lab::viewer
