// The progressive render on its own thread, so that the interface never waits on OpenCL (or on the
// host renderer's threads). The interface submits ViewStates and takes published frames; both
// hold the worker's lock only to copy. The worker renders in chunks sized to a time budget (one
// interface frame), publishes the image after each, and restarts accumulation when a newer state
// arrives. Where one sample of every pixel takes longer than a chunk, a new state is first rendered
// at a fraction of the size (a few samples, shown enlarged), then at full size: an edit shows after
// one small launch instead of a full one. A state the renderer refuses (a bad camera, a failed kernel build) is reported and the
// last good state is kept.
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
    int scale = 1;                    // > 1: a first pass rendered at 1/scale of the size, shown enlarged
};

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
    // The renderer's launch settings (for the pixel inspector's rays); false before it is made.
    bool kernel_settings(kernel::RenderKernelSettings* out) const;

private:
    void run();
    void apply(render::Renderer& renderer, const ViewState& state, const ViewState* applied);

    RendererFactory factory_;
    std::atomic<double> chunk_seconds_;
    int max_samples_;
    std::atomic<bool> stop_{false}, ready_{false};

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
