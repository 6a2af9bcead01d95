// Speed against accuracy of sampling strategies: the error of a render against a reference as a
// function of render time, on log-log axes, drawn by the embedded speed_accuracy_chart.py.
#pragma once

#include <string>
#include <vector>

namespace lab::plots {

// One sampling strategy: the error of its render after each time (same length, times increasing).
struct ConvergenceSeries {
    std::string name;
    std::vector<double> seconds;
    std::vector<double> rmse;
};

// A log-log chart of RMSE against render time, one line with markers per series, and a line of
// slope -1/2 (the Monte Carlo rate: error ~ 1/sqrt(samples) ~ 1/sqrt(time)) for comparison.
// csv_path may be empty; otherwise it gets one row per point:  series,seconds,rmse.
// Series without points, of unequal lengths, or with a time or error that is not finite and
// positive (a log axis cannot show it) are std::invalid_argument. Throws lab::InputError naming a
// path that cannot be written, std::runtime_error when no Python with matplotlib is found or the
// script fails.
// error_label names the error on the chart's axis (the series' `rmse` may hold a relative RMSE).
void write_speed_accuracy_chart(const std::vector<ConvergenceSeries>& series, const std::string& title, const std::string& png_path,
                                const std::string& csv_path, const std::string& error_label = "RMSE against the reference");

}  // namespace lab::plots
