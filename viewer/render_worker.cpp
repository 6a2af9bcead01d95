#include "viewer/render_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>

#include "viewer/display_denoiser.hpp"

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
constexpr int kMaxFirstPassScale = 16;
// Shares of a chunk: one whole first-pass sample, and one launch of the full-size passes (what a
// change waits for before it is applied).
constexpr double kFirstPassShare = 0.5;
constexpr double kLaunchShare = 0.25;

// The smallest integer reduction at which one sample of every pixel takes at most `budget`, at
// `pixel_seconds` per pixel and sample; while nothing was measured yet, the largest one (a cheap
// first measurement). The reduced image keeps at least 8 pixels a side.
int first_pass_scale(double pixel_seconds, double budget, int width, int height) {
    int scale = 1;
    auto fits = [&](int s) { return pixel_seconds > 0.0 && pixel_seconds * double(width / s) * double(height / s) <= budget; };
    while (!fits(scale) && scale < kMaxFirstPassScale && width / (scale + 1) >= 8 && height / (scale + 1) >= 8) ++scale;
    return scale;
}

// The small image at full size, filtered bilinearly between its pixel centres (a blur, as a
// viewport's first pass shows, rather than blocks).
film::ImageRgb enlarged(const film::ImageRgb& small, int width, int height) {
    film::ImageRgb out(width, height);
    const float sx = float(small.width) / float(width), sy = float(small.height) / float(height);
    for (int y = 0; y < height; ++y) {
        const float fy = std::clamp((float(y) + 0.5f) * sy - 0.5f, 0.0f, float(small.height - 1));
        const int y0 = int(fy), y1 = std::min(y0 + 1, small.height - 1);
        const float ty = fy - float(y0);
        for (int x = 0; x < width; ++x) {
            const float fx = std::clamp((float(x) + 0.5f) * sx - 0.5f, 0.0f, float(small.width - 1));
            const int x0 = int(fx), x1 = std::min(x0 + 1, small.width - 1);
            const float tx = fx - float(x0);
            float rgb[3];
            for (int c = 0; c < 3; ++c) {
                const float top = small.pixel(x0, y0)[c] * (1.0f - tx) + small.pixel(x1, y0)[c] * tx;
                const float bottom = small.pixel(x0, y1)[c] * (1.0f - tx) + small.pixel(x1, y1)[c] * tx;
                rgb[c] = top * (1.0f - ty) + bottom * ty;
            }
            out.set(x, y, rgb[0], rgb[1], rgb[2]);
        }
    }
    return out;
}

// Pixels for the next launch of a pass, from pixel `first` on, so that it takes about `budget`: the
// cost of each row as last measured there (the sky is cheap, the model dear), else `pixel_seconds`.
int launch_pixels(const std::vector<double>& row_seconds, double pixel_seconds, double budget, int first, int width) {
    if (pixel_seconds <= 0.0) return render::Renderer::kLaunchGranularity;  // nothing measured yet: a small launch measures
    double predicted = 0.0;
    int pixels = 0;
    for (size_t row = size_t(first / width); row < row_seconds.size() && predicted < budget; ++row) {
        const int in_row = pixels == 0 ? width - first % width : width;
        const double cost = row_seconds[row] > 0.0 ? row_seconds[row] : pixel_seconds;
        const int fit = int(std::min(double(in_row), (budget - predicted) / cost));
        pixels += std::max(fit, 1);
        predicted += double(std::max(fit, 1)) * cost;
    }
    return std::max(pixels, render::Renderer::kLaunchGranularity);
}

// Where the first full-size pass has not reached yet (pixels from `reached` on, in row order), the
// enlarged first pass shows instead: a display composite only, the film holds full-size samples.
void show_first_pass_beyond(film::ImageRgb* image, const film::ImageRgb& first_pass, int reached) {
    if (!first_pass.valid() || first_pass.width != image->width || first_pass.height != image->height) return;
    std::copy(first_pass.rgb.begin() + 3 * size_t(reached), first_pass.rgb.end(), image->rgb.begin() + 3 * size_t(reached));
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

void RenderWorker::set_denoise(bool on) {
    if (denoise_.exchange(on) == on) return;
    std::lock_guard<std::mutex> lock(mutex_);
    views_changed_ = true;
    wake_.notify_all();
}

void RenderWorker::want_views(bool film_statistics, bool first_hits) {
    if (want_film_statistics_.load() == film_statistics && want_first_hits_.load() == first_hits) return;
    std::lock_guard<std::mutex> lock(mutex_);
    want_film_statistics_.store(film_statistics);
    want_first_hits_.store(first_hits);
    views_changed_ = true;
    wake_.notify_all();
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
    bool restarted = false;
    if (!applied || !same_materials(s.materials, applied->materials)) {
        renderer.set_materials(s.materials);
        restarted = true;
    }
    if (!applied || !same_camera(s.camera, applied->camera)) {
        renderer.set_camera(s.camera);
        restarted = true;
    }
    if (!applied || s.env_rotation_degrees != applied->env_rotation_degrees || s.env_exposure_stops != applied->env_exposure_stops) {
        renderer.set_environment_transform(s.env_rotation_degrees, s.env_exposure_stops);
        restarted = true;
    }
    if (!applied || s.show_background != applied->show_background || s.background_opacity != applied->background_opacity ||
        s.background_blur_degrees != applied->background_blur_degrees) {
        renderer.set_background(s.show_background ? s.background_opacity : 0.0f, s.background_blur_degrees);
        restarted = true;
    }
    if (!restarted) renderer.reset();  // a state equal to the applied one still restarts: the user asked for it
}

struct RenderWorker::Loop {
    std::unique_ptr<render::Renderer> renderer;
    ViewState good;  // the last state the renderer accepted
    bool have_good = false;
    int width = 0, height = 0;   // the full size
    int scale = 1;               // the renderer's size is 1/scale of the full one
    double pixel_seconds = 0.0;  // one sample of one pixel, measured on the last launches; 0: not yet
    film::ImageRgb first_pass;   // the last first pass, enlarged: shown where the full size has not reached
    int first_pass_scale_shown = 1;
    std::shared_ptr<const render::FirstHitAovs> first_hits;  // of state first_hits_generation, at the full size
    uint64_t first_hits_generation = 0;
    uint64_t generation = 0, sequence = 0;
    std::unique_ptr<DisplayDenoiser> denoiser;  // of the full-size render of the current state
    std::vector<double> row_seconds;  // per pixel and sample, by full-size row, as last measured

    void measured(double seconds, int pixels) {
        if (pixels <= 0) return;
        const double m = seconds / double(pixels);
        // The cost differs across the image (the sky is cheap): follow a dearer launch at once.
        pixel_seconds = pixel_seconds > 0.0 ? std::max(m, 0.5 * (pixel_seconds + m)) : m;
    }
};

void RenderWorker::run() {
    Loop loop;
    loop.renderer = make_renderer();
    if (!loop.renderer) return;
    loop.renderer->set_samples_per_launch(1);  // small launches keep a chunk close to its budget
    try {
        // Builds the first-hit program (no samples: no march) before the first change can wait for it.
        loop.renderer->first_hit_aovs(render::SampleRanges());
    } catch (const std::exception&) {  // the views and the denoiser report it when they take the AOVs
    }
    loop.width = loop.renderer->settings().width;
    loop.height = loop.renderer->settings().height;
    loop.row_seconds.assign(size_t(loop.height), 0.0);
    loop.denoiser = std::make_unique<DisplayDenoiser>(loop.renderer->display_filter(), [this] {
        std::lock_guard<std::mutex> lock(mutex_);
        views_changed_ = true;  // a denoised image to publish, the render perhaps done
        wake_.notify_all();
    });
    while (!stop_.load()) {
        ViewState next;
        uint64_t next_generation = 0;
        if (!wait_for_work(loop, &next, &next_generation)) break;
        if (next_generation != 0 && !take_state(loop, next, next_generation)) return;
        try {
            render_chunk(loop);
        } catch (const std::exception& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = std::string("render failed: ") + e.what();
            status_ = "stopped";
            return;
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (loop.generation != pending_generation_) continue;  // not worth showing: apply the newer state first
        }
        publish(loop);
    }
}

std::unique_ptr<render::Renderer> RenderWorker::make_renderer() {
    std::unique_ptr<render::Renderer> renderer;
    try {
        renderer = factory_();
    } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        status_ = "no renderer";
        error_ = e.what();
        return nullptr;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        device_ = renderer->device_description();
        kernel_settings_ = renderer->kernel_settings(0, 1);
        status_ = "rendering on " + device_;
    }
    ready_.store(true);
    return renderer;
}

bool RenderWorker::wait_for_work(const Loop& loop, ViewState* next, uint64_t* next_generation) {
    std::unique_lock<std::mutex> lock(mutex_);
    // Rendered out: sleep until something changes, or what the display shows does (views, denoising).
    if (loop.generation == pending_generation_ && loop.renderer->samples_per_pixel() >= max_samples_)
        wake_.wait(lock, [&] { return stop_.load() || loop.generation != pending_generation_ || views_changed_; });
    views_changed_ = false;  // the chunk's publish takes the views and the denoising asked for
    if (stop_.load()) return false;
    if (loop.generation != pending_generation_) {
        *next = pending_;
        *next_generation = pending_generation_;
    }
    return true;
}

bool RenderWorker::take_state(Loop& loop, const ViewState& next, uint64_t next_generation) {
    render::Renderer& renderer = *loop.renderer;
    try {
        apply(renderer, next, loop.have_good ? &loop.good : nullptr);
        loop.good = next;
        loop.have_good = true;
        std::lock_guard<std::mutex> lock(mutex_);
        error_.clear();
    } catch (const std::exception& e) {
        // Keep what was shown: back to the last good state (or stop, when there is none).
        std::lock_guard<std::mutex> lock(mutex_);
        error_ = e.what();
        if (!loop.have_good) {
            status_ = "no renderer";
            return false;
        }
        try {
            apply(renderer, loop.good, nullptr);
        } catch (const std::exception&) {
            status_ = "no renderer";
            return false;
        }
    }
    loop.generation = next_generation;
    loop.first_pass = film::ImageRgb();
    loop.denoiser->restart();
    // A new full size (the window's render area changed): the cost per pixel measured so far still holds.
    const bool resized = next.width > 0 && next.height > 0 && (next.width != loop.width || next.height != loop.height);
    if (resized) {
        loop.width = next.width;
        loop.height = next.height;
        loop.row_seconds.assign(size_t(loop.height), 0.0);
    }
    const int wanted = first_pass_scale(loop.pixel_seconds, kFirstPassShare * chunk_seconds_.load(), loop.width, loop.height);
    if (wanted != loop.scale || resized) {
        renderer.resize(loop.width / wanted, loop.height / wanted);  // resets
        loop.scale = wanted;
    }
    return true;
}

void RenderWorker::render_chunk(Loop& loop) {
    render::Renderer& renderer = *loop.renderer;
    const auto chunk_start = std::chrono::steady_clock::now();
    auto since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    if (loop.scale > 1) {
        // One whole sample of the small image (it was sized to take part of a chunk).
        renderer.set_launch_pixels(0);
        if (renderer.samples_per_pixel() < std::min(kFirstPassSamples, max_samples_)) {
            renderer.add_samples(1);
            loop.measured(since(chunk_start), renderer.settings().width * renderer.settings().height);
        }
        return;
    }
    // Launches of part of the image until the chunk is spent, a newer state waits, or the first
    // full pass is complete; a newer state waits at most one launch.
    const int width = loop.width;
    const int first_spp = renderer.samples_per_pixel();
    while (renderer.samples_per_pixel() < max_samples_) {
        const int before = renderer.pass_pixels();
        renderer.set_launch_pixels(launch_pixels(loop.row_seconds, loop.pixel_seconds, kLaunchShare * chunk_seconds_.load(), before, width));
        const auto launch_start = std::chrono::steady_clock::now();
        renderer.add_samples(max_samples_ - renderer.samples_per_pixel(), 0.0);  // one launch
        const int after = renderer.pass_pixels(), end = after > before ? after : width * loop.height;
        const double seconds = since(launch_start);
        loop.measured(seconds, end - before);
        for (int row = before / width; row <= (end - 1) / width; ++row) loop.row_seconds[size_t(row)] = seconds / double(end - before);
        if (since(chunk_start) >= chunk_seconds_.load() || (first_spp == 0 && renderer.samples_per_pixel() > 0)) break;
        std::lock_guard<std::mutex> lock(mutex_);
        if (loop.generation != pending_generation_ || stop_.load()) break;
    }
}

void RenderWorker::publish(Loop& loop) {
    render::Renderer& renderer = *loop.renderer;
    film::ImageRgb image = renderer.image();  // outside the lock: the interface keeps drawing
    int shown_scale = loop.scale;
    if (loop.scale > 1) {
        image = enlarged(image, loop.width, loop.height);
        loop.first_pass = image;
        loop.first_pass_scale_shown = loop.scale;
    } else if (renderer.samples_per_pixel() == 0 && loop.first_pass.valid()) {
        show_first_pass_beyond(&image, loop.first_pass, renderer.pass_pixels());
        shown_scale = loop.first_pass_scale_shown;
    }
    // Asked between the pieces of a first-hit march: a newer state ends it.
    const std::function<bool()> changed = [&] {
        std::lock_guard<std::mutex> lock(mutex_);
        return loop.generation != pending_generation_ || stop_.load();
    };
    int denoised_samples = 0;
    if (denoise_.load() && loop.scale == 1 && renderer.samples_per_pixel() > 0) {
        try {
            image = loop.denoiser->shown(renderer, image, renderer.samples_per_pixel() >= max_samples_, changed, &denoised_samples);
        } catch (const std::exception& e) {  // the filter's kernel failed: show the raw image, say why
            denoise_.store(false);
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = std::string("denoising failed: ") + e.what();
        }
    }
    render::RenderStatistics stats = renderer.statistics();
    if (loop.scale > 1 && stats.samples_per_pixel >= std::min(kFirstPassSamples, max_samples_)) {
        try {
            renderer.resize(loop.width, loop.height);  // the full size from the next chunk on, on a film of its own
            loop.scale = 1;
        } catch (const std::exception& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = e.what();
        }
    }
    // The views' inputs, at the full size only (the first pass is another size).
    film::ImageRgb variance;
    std::vector<float> samples;
    const bool full_size = loop.scale == 1 && shown_scale == 1;
    if (full_size && want_film_statistics_.load()) {
        variance = renderer.variance();
        samples = renderer.sample_counts();
    }
    if (full_size && want_first_hits_.load() && loop.first_hits_generation != loop.generation) {
        try {
            std::optional<render::FirstHitAovs> first_hits = renderer.first_hit_aovs(render::SampleRanges(0, kViewFirstHitSamples), changed);
            if (first_hits) {
                loop.first_hits = std::make_shared<const render::FirstHitAovs>(std::move(*first_hits));
                loop.first_hits_generation = loop.generation;
            }
        } catch (const std::exception& e) {  // a failed build of the first-hit program: the views say so
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = e.what();
        }
    }
    std::lock_guard<std::mutex> lock(mutex_);
    published_.variance = std::move(variance);
    published_.samples = std::move(samples);
    published_.first_hits = full_size && loop.first_hits_generation == loop.generation ? loop.first_hits : nullptr;
    published_.scale = shown_scale;
    published_.denoised_samples = denoised_samples;
    published_.image = std::move(image);
    published_.samples_per_pixel = stats.samples_per_pixel;
    published_.samples_per_second = stats.paths_per_second();
    published_.generation = loop.generation;
    published_.sequence = ++loop.sequence;
}

}  // namespace lab::viewer
