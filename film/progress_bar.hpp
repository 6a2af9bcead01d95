// Progress of a long render on stderr:
//   samples: [##########----------]  128/256 spp  1.93 M paths/s  ETA 0:04
//   time:    [######--------------]  12.0/30.0 s  93 spp  1.93 M paths/s
// On a terminal one line is redrawn in place (at most every redraw_interval_seconds); in a log (not
// a terminal) a plain line is printed each time another 10% is done, so CI logs stay short.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>

namespace lab::film {

enum class ProgressMode { Samples, Time };

struct ProgressState {
    ProgressMode mode = ProgressMode::Samples;
    int samples = 0;                   // samples per pixel done
    int target_samples = 0;            // Samples mode: the goal
    double elapsed_seconds = 0.0;
    double time_budget_seconds = 0.0;  // Time mode: the goal
    double paths_per_second = 0.0;     // 0 while unknown
};

// Done part of the goal, in [0, 1].
double progress_fraction(const ProgressState& state);

// Three significant digits with an SI prefix: "1.93 M paths/s", "950 k paths/s", "12.0 paths/s";
// "- paths/s" while unknown (zero, negative or not finite).
std::string format_rate(double paths_per_second);

// Whole seconds, rounded: "0:04", "12:30", "1:02:03".
std::string format_duration(double seconds);

// The whole line, without a line break (see the top of this file). In Samples mode the count is
// padded to the target's width so the line does not jitter; the ETA is the remaining samples at
// the rate so far, "ETA -:--" before the first sample.
std::string format_progress(const ProgressState& state, int bar_width = 20);

struct ProgressOptions {
    bool quiet = false;                    // print nothing at all
    std::ostream* out = nullptr;           // nullptr: std::cerr
    std::optional<bool> terminal;          // unset: whether stderr is a terminal (false when `out` is set)
    std::function<double()> clock;         // seconds from any fixed origin; unset: std::chrono::steady_clock
    int bar_width = 20;
    double redraw_interval_seconds = 0.1;  // terminal only
};

class ProgressBar {
public:
    // target: the samples per pixel to reach (Samples) or the seconds to render (Time).
    // paths_per_sample: paths traced per sample per pixel pass, usually width * height.
    // The clock starts now.
    ProgressBar(ProgressMode mode, double target, double paths_per_sample, ProgressOptions options = {});
    ~ProgressBar();  // ends a line left open on a terminal (e.g. when the render threw)
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // After each sample pass: the samples per pixel done so far.
    void update(int samples_done);
    // The last state, always shown (unless quiet or already printed), then a line break on a terminal.
    void finish();

    double elapsed_seconds() const;
    ProgressState state() const;

private:
    void draw(const ProgressState& s);

    ProgressMode mode_;
    double target_, paths_per_sample_;
    ProgressOptions options_;
    std::ostream* out_;
    bool terminal_;
    double start_;
    int samples_ = 0;
    double last_draw_ = -1.0;   // clock time of the last redraw (terminal)
    int printed_decile_ = 0;    // the last tenth printed (log)
    int printed_samples_ = -1;  // samples of the last line printed (log)
    size_t line_length_ = 0;    // of the line on screen (terminal), to blank a longer old one
    bool line_open_ = false, finished_ = false;
};

}  // namespace lab::film
