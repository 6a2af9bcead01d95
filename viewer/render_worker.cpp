#include "viewer/render_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>

namespace lab::viewer {

namespace {

bool same_materials(const std::vector<brdf::Material>& a, const std::vector<brdf::Material>& b) {
    // Material is plain data written once per field: comparing the bytes is comparing the fields.
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(brdf::Material)) == 0);
}

bool same_camera(const scene::Camera& a, const scene::Camera& b) {
    return a.type == b.type && a.position == b.position && a.look_at == b.look_at && a.up == b.up && a.fov_degrees == b.fov_degrees &&
           a.aperture_radius == b.aperture_radius && a.focus_distance == b.focus_distance;
}

// Samples per pixel of the small first pass before the full size takes over.
constexpr int kFirstPassSamples = 4;
constexpr int kMaxFirstPassScale = 8;

// The smallest power-of-two reduction whose launch (one sample per pixel) fits in a chunk.
int first_pass_scale(double full_launch_seconds, double chunk_seconds, int width, int height) {
    int scale = 1;
    while (full_launch_seconds / double(scale * scale) > chunk_seconds && scale < kMaxFirstPassScale && width / (scale * 2) >= 8 &&
           height / (scale * 2) >= 8)
        scale *= 2;
    return scale;
}

// The small image at full size, each pixel repeated (nearest).
film::ImageRgb enlarged(const film::ImageRgb& small, int width, int height) {
    film::ImageRgb out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* p = small.pixel(x * small.width / width, y * small.height / height);
            out.set(x, y, p[0], p[1], p[2]);
        }
    return out;
}

}  // namespace

RenderWorker::RenderWorker(RendererFactory factory, const ViewState& initial, double chunk_seconds, int max_samples)
    : factory_(std::move(factory)), chunk_seconds_(chunk_seconds), max_samples_(max_samples), pending_(initial) {
    thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() {
    stop_.store(true);
    wake_.notify_all();
    thread_.join();  // waits for at most one chunk
}

uint64_t RenderWorker::submit(const ViewState& state) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = state;
    ++pending_generation_;
    wake_.notify_all();
    return pending_generation_;
}

bool RenderWorker::take_frame(RenderFrame* out) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (published_.sequence <= out->sequence) return false;
    *out = published_;
    return true;
}

std::string RenderWorker::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
}

std::string RenderWorker::error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
}

bool RenderWorker::kernel_settings(kernel::RenderKernelSettings* out) const {
    if (!ready_.load()) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    *out = kernel_settings_;
    return true;
}

std::string RenderWorker::device_description() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return device_;
}

// Only what differs from the state already applied is set: each setter resets the film, and a
// material with new BRDF features rebuilds the kernel.
void RenderWorker::apply(render::Renderer& renderer, const ViewState& s, const ViewState* applied) {
    if (!applied || !same_materials(s.materials, applied->materials)) renderer.set_materials(s.materials);
    if (!applied || !same_camera(s.camera, applied->camera)) renderer.set_camera(s.camera);
    if (!applied || s.env_rotation_degrees != applied->env_rotation_degrees || s.env_exposure_stops != applied->env_exposure_stops)
        renderer.set_environment_transform(s.env_rotation_degrees, s.env_exposure_stops);
    if (!applied || s.show_background != applied->show_background) renderer.set_show_background(s.show_background);
    renderer.reset();  // a state equal to the applied one still restarts: the user asked for it
}

void RenderWorker::run() {
    std::unique_ptr<render::Renderer> renderer;
    try {
        renderer = factory_();
    } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        status_ = "no renderer";
        error_ = e.what();
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        device_ = renderer->device_description();
        kernel_settings_ = renderer->kernel_settings(0, 1);
        status_ = "rendering on " + device_;
    }
    ready_.store(true);
    renderer->set_samples_per_launch(1);  // small launches keep a chunk close to its budget

    ViewState good;              // the last state the renderer accepted
    bool have_good = false;
    const int width = renderer->settings().width, height = renderer->settings().height;
    int scale = 1;                    // the renderer's size is 1/scale of the full one
    double full_launch_seconds = 0.0; // one sample per pixel at full size, measured; 0: not yet
    uint64_t generation = 0, sequence = 0;
    while (!stop_.load()) {
        ViewState next;
        uint64_t next_generation = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            // Rendered out: sleep until something changes.
            if (generation == pending_generation_ && renderer->statistics().samples_per_pixel >= max_samples_)
                wake_.wait(lock, [&] { return stop_.load() || generation != pending_generation_; });
            if (stop_.load()) break;
            if (generation != pending_generation_) {
                next = pending_;
                next_generation = pending_generation_;
            }
        }
        if (next_generation != 0) {
            try {
                apply(*renderer, next, have_good ? &good : nullptr);
                good = next;
                have_good = true;
                std::lock_guard<std::mutex> lock(mutex_);
                error_.clear();
            } catch (const std::exception& e) {
                // Keep what was shown: back to the last good state (or stop, when there is none).
                std::lock_guard<std::mutex> lock(mutex_);
                error_ = e.what();
                if (!have_good) {
                    status_ = "no renderer";
                    return;
                }
                try {
                    apply(*renderer, good, nullptr);
                } catch (const std::exception&) {
                    status_ = "no renderer";
                    return;
                }
            }
            generation = next_generation;
            const int wanted = first_pass_scale(full_launch_seconds, chunk_seconds_.load(), width, height);
            if (wanted != scale) {
                renderer->resize(width / wanted, height / wanted);  // resets
                scale = wanted;
            }
        }
        try {
            int left = max_samples_ - renderer->statistics().samples_per_pixel;
            if (scale > 1) left = std::min(left, std::min(kFirstPassSamples, max_samples_) - renderer->statistics().samples_per_pixel);
            if (left > 0) {
                const auto start = std::chrono::steady_clock::now();
                const int added = renderer->add_samples(left, chunk_seconds_.load());
                const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (scale == 1 && added > 0) full_launch_seconds = seconds / double(added);
            }
        } catch (const std::exception& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = std::string("render failed: ") + e.what();
            status_ = "stopped";
            return;
        }
        film::ImageRgb image = renderer->image();  // outside the lock: the interface keeps drawing
        if (scale > 1) image = enlarged(image, width, height);
        render::RenderStatistics stats = renderer->statistics();
        const int shown_scale = scale;
        if (scale > 1 && stats.samples_per_pixel >= std::min(kFirstPassSamples, max_samples_)) {
            try {
                renderer->resize(width, height);  // the full size from the next chunk on
                scale = 1;
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(mutex_);
                error_ = e.what();
            }
        }
        std::lock_guard<std::mutex> lock(mutex_);
        published_.scale = shown_scale;
        published_.image = std::move(image);
        published_.samples_per_pixel = stats.samples_per_pixel;
        published_.samples_per_second = stats.paths_per_second();
        published_.generation = generation;
        published_.sequence = ++sequence;
    }
}

}  // namespace lab::viewer
