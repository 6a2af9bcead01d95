#include "film/progress_bar.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace lab::film {

namespace {

double steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int digits(int n) { return int(std::to_string(std::max(n, 0)).size()); }

}  // namespace

double progress_fraction(const ProgressState& s) {
    double f = 0.0;
    if (s.mode == ProgressMode::Samples)
        f = s.target_samples > 0 ? double(s.samples) / double(s.target_samples) : 1.0;
    else
        f = s.time_budget_seconds > 0.0 ? s.elapsed_seconds / s.time_budget_seconds : 1.0;
    return std::isfinite(f) ? std::min(std::max(f, 0.0), 1.0) : 0.0;
}

std::string format_rate(double v) {
    if (!(v > 0.0) || !std::isfinite(v)) return "- paths/s";
    static const char* const prefixes[] = {"", " k", " M", " G", " T"};
    int k = 0;
    while (v >= 999.5 && k < 4) v /= 1000.0, ++k;  // 999.5 would print as "1000"
    char text[48];
    std::snprintf(text, sizeof text, v < 9.995 ? "%.2f%s paths/s" : v < 99.95 ? "%.1f%s paths/s" : "%.0f%s paths/s", v, prefixes[k]);
    return text;
}

std::string format_duration(double seconds) {
    const long s = std::isfinite(seconds) ? std::max(0L, std::lround(seconds)) : 0L;
    char text[32];
    if (s >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

std::string format_progress(const ProgressState& s, int bar_width) {
    const int filled = int(std::floor(progress_fraction(s) * bar_width + 1e-9));
    std::string line = "[" + std::string(size_t(filled), '#') + std::string(size_t(bar_width - filled), '-') + "]  ";
    char text[96];
    if (s.mode == ProgressMode::Samples) {
        std::snprintf(text, sizeof text, "%*d/%d spp  ", digits(s.target_samples), s.samples, s.target_samples);
        line += text + format_rate(s.paths_per_second) + "  ETA ";
        line += s.samples > 0 ? format_duration(s.elapsed_seconds * double(s.target_samples - s.samples) / double(s.samples)) : "-:--";
    } else {
        std::snprintf(text, sizeof text, "%.1f/%.1f s  %d spp  ", s.elapsed_seconds, s.time_budget_seconds, s.samples);
        line += text + format_rate(s.paths_per_second);
    }
    return line;
}

ProgressBar::ProgressBar(ProgressMode mode, double target, double paths_per_sample, ProgressOptions options)
    : mode_(mode), target_(target), paths_per_sample_(paths_per_sample), options_(std::move(options)) {
    if (!options_.clock) options_.clock = steady_seconds;
    out_ = options_.out ? options_.out : &std::cerr;
    terminal_ = options_.terminal.value_or(options_.out == nullptr && ::isatty(STDERR_FILENO) == 1);
    start_ = options_.clock();
}

ProgressBar::~ProgressBar() {
    if (line_open_) *out_ << '\n' << std::flush;
}

double ProgressBar::elapsed_seconds() const { return options_.clock() - start_; }

ProgressState ProgressBar::state() const {
    ProgressState s;
    s.mode = mode_;
    s.samples = samples_;
    s.elapsed_seconds = elapsed_seconds();
    if (mode_ == ProgressMode::Samples)
        s.target_samples = int(target_);
    else
        s.time_budget_seconds = target_;
    if (s.elapsed_seconds > 0.0) s.paths_per_second = double(samples_) * paths_per_sample_ / s.elapsed_seconds;
    return s;
}

void ProgressBar::draw(const ProgressState& s) {
    const std::string line = format_progress(s, options_.bar_width);
    if (terminal_) {
        // \r returns to the start of the line; spaces blank what a longer old line left
        *out_ << '\r' << line << std::string(line_length_ > line.size() ? line_length_ - line.size() : 0, ' ') << std::flush;
        line_length_ = line.size();
        line_open_ = true;
    } else {
        *out_ << line << '\n' << std::flush;
        printed_samples_ = s.samples;
    }
}

void ProgressBar::update(int samples_done) {
    samples_ = samples_done;
    if (options_.quiet || finished_) return;
    const ProgressState s = state();
    if (terminal_) {
        const double now = options_.clock();
        if (last_draw_ >= 0.0 && now - last_draw_ < options_.redraw_interval_seconds) return;
        last_draw_ = now;
        draw(s);
        return;
    }
    const int decile = int(std::floor(progress_fraction(s) * 10.0 + 1e-9));
    if (decile > printed_decile_) {
        printed_decile_ = decile;
        draw(s);
    }
}

void ProgressBar::finish() {
    if (options_.quiet || finished_) return;
    finished_ = true;
    if (terminal_) {
        draw(state());
        *out_ << '\n' << std::flush;
        line_open_ = false;
    } else if (printed_decile_ < 10 || printed_samples_ != samples_) {
        draw(state());  // the final state, unless the 100% line already showed it
    }
}

}  // namespace lab::film
