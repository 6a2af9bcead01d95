#include "viewer/display_denoiser.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "render/display_denoise.hpp"

namespace lab::viewer {

namespace {

bool stall_asked() {
    const char* value = std::getenv("DTOADQ_DEBUG_STALL_DENOISER");
    return value && std::strcmp(value, "1") == 0;
}

}  // namespace

DisplayDenoiser::DisplayDenoiser(std::unique_ptr<render::DisplayFilter> filter, std::function<void()> on_filtered)
    : filter_(std::move(filter)), on_filtered_(std::move(on_filtered)), stall_(stall_asked()) {
    thread_ = std::thread([this] { run(); });
}

DisplayDenoiser::~DisplayDenoiser() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        ++epoch_;  // cancels a running filter at its next pass
    }
    wake_.notify_all();
    thread_.join();
}

void DisplayDenoiser::restart() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        ++epoch_;
        job_.reset();
    }
    first_hits_ = render::FirstHitAovs();
    guide_samples_ = 0;
    last_ = film::ImageRgb();
    last_samples_ = 0;
    requested_samples_ = 0;
}

film::ImageRgb DisplayDenoiser::shown(const render::Renderer& renderer, const film::ImageRgb& raw, bool last, const std::function<bool()>& changed,
                                      int* shown_samples) {
    bool busy = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_.empty()) {
            const std::string error = std::move(error_);
            error_.clear();
            throw std::runtime_error(error);
        }
        if (result_epoch_ == epoch_.load() && result_samples_ > last_samples_) {
            last_ = std::move(result_);
            last_samples_ = result_samples_;
            cost_seconds_ = result_cost_;
            last_run_ = result_end_;
        }
        busy = running_ || job_.has_value();
    }
    const int samples = renderer.samples_per_pixel();
    const double since_last = std::chrono::duration<double>(Clock::now() - last_run_).count();
    const bool first = requested_samples_ == 0;
    const bool due = !busy && samples > requested_samples_ && (first || last || since_last * kTimeShare >= cost_seconds_ * (1.0 - kTimeShare));
    if (due && renderer.pass_pixels() == 0 && samples > 0 && (guide_samples_ == 0 || (samples >= 2 * guide_samples_ && guide_samples_ < kGuideSamples))) {
        std::optional<render::FirstHitAovs> guide = renderer.first_hit_aovs(renderer.sample_ranges(), changed);
        if (guide) {
            first_hits_ = std::move(*guide);
            guide_samples_ = samples;
        }
    }
    if (due && guide_samples_ > 0 && !changed()) {
        Job job{raw, render::denoise_guide(first_hits_, renderer.variance()), samples, 0};
        requested_samples_ = samples;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            job.epoch = epoch_.load();
            job_ = std::move(job);
        }
        wake_.notify_all();
    }
    *shown_samples = last_samples_;
    return last_samples_ > 0 ? last_ : raw;
}

void DisplayDenoiser::run() {
    try {
        filter_->prepare();  // its program, while the renderer builds its own: not at the first filter, beside a change
    } catch (const std::exception&) {  // the first filter throws it again, and the worker reports it
    }
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || job_.has_value(); });
            if (stop_) return;
            job = std::move(*job_);
            job_.reset();
            running_ = true;
        }
        if (stall_) {
            std::fprintf(stderr, "display denoiser: stalled until the viewer closes (DTOADQ_DEBUG_STALL_DENOISER)\n");
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_; });
            return;
        }
        const Clock::time_point start = Clock::now();
        film::ImageRgb image;
        std::string error;
        try {
            image = render::denoised(job.raw, job.guide, *filter_, [&] { return epoch_.load() != job.epoch; });
        } catch (const std::exception& e) {
            error = e.what();
        }
        bool filtered = false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            running_ = false;
            if (!error.empty()) {
                error_ = error;
            } else if (image.valid() && job.epoch == epoch_.load()) {
                result_ = std::move(image);
                result_samples_ = job.samples;
                result_epoch_ = job.epoch;
                result_end_ = Clock::now();
                result_cost_ = std::chrono::duration<double>(result_end_ - start).count();
                filtered = true;
            }
        }
        if (filtered || !error.empty()) on_filtered_();
    }
}

}  // namespace lab::viewer
