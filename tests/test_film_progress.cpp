// The progress display: its text, exactly, and when lines are printed (with a fake clock).
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "film/progress_bar.hpp"

using lab::film::ProgressMode;
using lab::film::ProgressState;

namespace {

ProgressState samples_state(int done, int target, double elapsed, double rate) {
    ProgressState s;
    s.mode = ProgressMode::Samples;
    s.samples = done;
    s.target_samples = target;
    s.elapsed_seconds = elapsed;
    s.paths_per_second = rate;
    return s;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("progress text: rates, durations and whole lines, exactly", "[film]") {
    CHECK(lab::film::format_rate(1.93e6) == "1.93 M paths/s");
    CHECK(lab::film::format_rate(950e3) == "950 k paths/s");
    CHECK(lab::film::format_rate(12.0) == "12.0 paths/s");
    CHECK(lab::film::format_rate(999.4) == "999 paths/s");
    CHECK(lab::film::format_rate(999.5) == "1.00 k paths/s");
    CHECK(lab::film::format_rate(2.5e10) == "25.0 G paths/s");
    CHECK(lab::film::format_rate(0.0) == "- paths/s");
    CHECK(lab::film::format_duration(4.0) == "0:04");
    CHECK(lab::film::format_duration(59.6) == "1:00");
    CHECK(lab::film::format_duration(750.0) == "12:30");
    CHECK(lab::film::format_duration(3723.0) == "1:02:03");

    CHECK(lab::film::format_progress(samples_state(128, 256, 4.0, 1.93e6)) == "[##########----------]  128/256 spp  1.93 M paths/s  ETA 0:04");
    CHECK(lab::film::format_progress(samples_state(8, 256, 1.0, 950e3)) == "[--------------------]    8/256 spp  950 k paths/s  ETA 0:31");
    CHECK(lab::film::format_progress(samples_state(0, 16, 0.0, 0.0)) == "[--------------------]   0/16 spp  - paths/s  ETA -:--");
    CHECK(lab::film::format_progress(samples_state(16, 16, 2.0, 5e5), 10) == "[##########]  16/16 spp  500 k paths/s  ETA 0:00");

    ProgressState t;
    t.mode = ProgressMode::Time;
    t.samples = 93;
    t.elapsed_seconds = 12.0;
    t.time_budget_seconds = 30.0;
    t.paths_per_second = 1.93e6;
    CHECK(lab::film::format_progress(t) == "[########------------]  12.0/30.0 s  93 spp  1.93 M paths/s");
    t.elapsed_seconds = 30.04;  // a render ends a little after its budget; the bar stays full
    CHECK(lab::film::format_progress(t, 10) == "[##########]  30.0/30.0 s  93 spp  1.93 M paths/s");
}

TEST_CASE("in a log the progress is one line per 10%", "[film]") {
    double now = 100.0;
    std::ostringstream log;
    lab::film::ProgressOptions options;
    options.out = &log;
    options.terminal = false;
    options.clock = [&] { return now; };
    {
        lab::film::ProgressBar bar(ProgressMode::Samples, 100, 1000.0, options);
        for (int spp = 1; spp <= 100; ++spp) {
            now += 0.5;
            bar.update(spp);
        }
        bar.finish();
    }
    std::vector<std::string> lines = lines_of(log.str());
    REQUIRE(lines.size() == 10u);  // finish adds nothing: the 100% line is the final state
    CHECK(lines[0] == "[##------------------]   10/100 spp  2.00 k paths/s  ETA 0:45");
    CHECK(lines[9] == "[####################]  100/100 spp  2.00 k paths/s  ETA 0:00");
    CHECK(log.str().find('\r') == std::string::npos);
}

TEST_CASE("in a log a time-limited render also prints its final state", "[film]") {
    double now = 0.0;
    std::ostringstream log;
    lab::film::ProgressOptions options;
    options.out = &log;
    options.terminal = false;
    options.clock = [&] { return now; };
    lab::film::ProgressBar bar(ProgressMode::Time, 10.0, 100.0, options);
    for (int spp = 1; now < 9.75; ++spp) {  // 0.75 s per pass
        now += 0.75;
        bar.update(spp);
    }
    bar.finish();
    std::vector<std::string> lines = lines_of(log.str());
    REQUIRE(lines.size() == 10u);  // 10%..90% as they were passed, then the final state at 9.75 s
    CHECK(lines[0] == "[###-----------------]  1.5/10.0 s  2 spp  133 paths/s");
    CHECK(lines[8] == "[##################--]  9.0/10.0 s  12 spp  133 paths/s");
    CHECK(lines[9] == "[###################-]  9.8/10.0 s  13 spp  133 paths/s");
}

TEST_CASE("on a terminal the line is redrawn in place, at most every interval - quiet prints nothing", "[film]") {
    double now = 0.0;
    std::ostringstream screen;
    lab::film::ProgressOptions options;
    options.out = &screen;
    options.terminal = true;
    options.clock = [&] { return now; };
    options.redraw_interval_seconds = 1.0;
    {
        lab::film::ProgressBar bar(ProgressMode::Samples, 100, 10.0, options);
        for (int spp = 1; spp <= 100; ++spp) {
            now += 0.25;
            bar.update(spp);
        }
        bar.finish();
    }
    const std::string text = screen.str();
    CHECK(std::count(text.begin(), text.end(), '\r') == 26);  // at 0.25, 1.25, ..., 24.25 s, and the final state
    CHECK(std::count(text.begin(), text.end(), '\n') == 1);
    CHECK(text.rfind("\r[--------------------]    1/100 spp  40.0 paths/s  ETA 0:25", 0) == 0);
    CHECK(text.substr(text.rfind('\r')) == "\r[####################]  100/100 spp  40.0 paths/s  ETA 0:00\n");

    // a render that throws still leaves the terminal on a fresh line
    std::ostringstream interrupted;
    options.out = &interrupted;
    { lab::film::ProgressBar bar(ProgressMode::Samples, 10, 10.0, options); bar.update(1); }
    CHECK(interrupted.str().back() == '\n');

    std::ostringstream silent;
    options.out = &silent;
    options.quiet = true;
    {
        lab::film::ProgressBar bar(ProgressMode::Samples, 10, 10.0, options);
        for (int spp = 1; spp <= 10; ++spp) bar.update(spp);
        bar.finish();
    }
    CHECK(silent.str().empty());
}
