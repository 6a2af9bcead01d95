// The progressive render on its own thread, so that the interface never waits on OpenCL (or on the
// host renderer's threads). The interface submits ViewStates and takes published frames; both
// hold the worker's lock only to copy. The worker renders in chunks sized to a time budget (one
// interface frame) and publishes the image after each. So that an edit shows in the next frame:
// - full-size passes run as launches over part of the image (Renderer::set_launch_pixels) of about
//   a quarter of a chunk, and a newer state is looked for after each: it waits one such launch;
// - a new state is first rendered at a reduced size, the smallest integer reduction at which one
//   sample of every pixel takes half a chunk (measured), published after each of its few samples
//   and shown enlarged; then the full size starts on a film of its own, and until its first pass is
//   complete the enlarged first pass shows where that pass has not reached yet.
// The full-size image never holds a sample of the first pass. A state the renderer refuses (a bad
// camera, a failed kernel build) is reported and the last good state is kept. With set_denoise(true)
// the full-size image is published denoised (viewer/display_denoiser.hpp), the film untouched.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "film/image.hpp"
#include "render/renderer.hpp"
#include "viewer/view_state.hpp"

namespace lab::viewer {

// A published image: the mean so far of the state with the given generation.
struct RenderFrame {
    film::ImageRgb image;
    int samples_per_pixel = 0;
    double samples_per_second = 0.0;  // paths (one per pixel and sample) per second of rendering
    uint64_t generation = 0;          // of the ViewState it shows
    uint64_t sequence = 0;            // counts publications
    int scale = 1;                    // > 1: a first pass rendered at 1/scale of the size, shown enlarged (alone, or where
                                      // the first full-size pass has not reached: then samples_per_pixel is 0)
    int denoised_samples = 0;         // > 0: the image is denoised (viewer/display_denoiser.hpp), filtered from this many samples per pixel
    // What the view menu's other views show (viewer/view_modes), at the full size only and when
    // asked for (RenderWorker::want_views); else empty. The film's, with the image:
    film::ImageRgb variance;          // of each pixel's mean
    std::vector<float> samples;       // finite samples per pixel
    // The first-hit AOVs of the state, over its first kViewFirstHitSamples sample indices: made
    // once per state, shared by the frames that show it.
    std::shared_ptr<const render::FirstHitAovs> first_hits;
};

// Sample indices the views' first-hit AOVs are averaged over: an antialiased edge, at a few
// marches per pixel once per state.
constexpr int kViewFirstHitSamples = 4;

class RenderWorker {
public:
    using RendererFactory = std::function<std::unique_ptr<render::Renderer>()>;
    // Starts the thread; the renderer is made (its kernel built) there. The first state is `initial`.
    RenderWorker(RendererFactory factory, const ViewState& initial, double chunk_seconds, int max_samples);
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    // A new state; returns its generation. Never blocks on rendering.
    uint64_t submit(const ViewState& state);
    // Copies the latest frame into *out when it is newer than out->sequence; returns whether it did.
    bool take_frame(RenderFrame* out);
    // One line: "building kernel", "rendering on DEVICE", the last error (empty: none).
    std::string status() const;
    std::string error() const;
    // The renderer, when made (for its description and compiled scene); null before.
    bool ready() const { return ready_.load(); }
    std::string device_description() const;
    void set_chunk_seconds(double s) { chunk_seconds_.store(s); }
    // Whether the published image is denoised (viewer/display_denoiser.hpp); the film is not
    // touched, so a change only publishes the image again.
    void set_denoise(bool on);
    // Which of RenderFrame's view inputs to publish from now on (each costs time on the worker); a
    // change publishes a frame even when the render is done.
    void want_views(bool film_statistics, bool first_hits);
    // The renderer's launch settings (for the pixel inspector's rays); false before it is made.
    bool kernel_settings(kernel::RenderKernelSettings* out) const;

private:
    // What the worker's thread keeps between chunks (render_worker.cpp).
    struct Loop;

    void run();
    // Makes the renderer and tells the interface its device; null (with the error) on failure.
    std::unique_ptr<render::Renderer> make_renderer();
    // Sleeps while rendered out and nothing changes; a newer state into *next (its generation, or
    // 0 when none waits). False: stop.
    bool wait_for_work(const Loop& loop, ViewState* next, uint64_t* next_generation);
    // Applies a newer state, back to the last good one when it fails, and picks the first pass's
    // scale. False: no state can be rendered.
    bool take_state(Loop& loop, const ViewState& next, uint64_t next_generation);
    // A chunk of samples: one whole sample of the small first pass, or launches of part of the full image.
    void render_chunk(Loop& loop);
    // The image as it is now, and the statistics, for the interface; the full size after the first pass.
    void publish(Loop& loop);
    void apply(render::Renderer& renderer, const ViewState& state, const ViewState* applied);

    RendererFactory factory_;
    std::atomic<double> chunk_seconds_;
    int max_samples_;
    std::atomic<bool> stop_{false}, ready_{false};
    std::atomic<bool> denoise_{false};
    std::atomic<bool> want_film_statistics_{false}, want_first_hits_{false};
    bool views_changed_ = false;  // under mutex_: want_views or set_denoise asked for another display

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    ViewState pending_;
    uint64_t pending_generation_ = 1;
    RenderFrame published_;
    std::string status_ = "building kernel", error_, device_;
    kernel::RenderKernelSettings kernel_settings_{};
    std::thread thread_;
};

}  // namespace lab::viewer
