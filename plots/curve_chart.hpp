// Curves of one quantity against another on log-log axes (the stability atlas: the hit error of a
// float march against the distance from the origin), each a measured series or a reference level
// (a threshold, a closed form) drawn dashed, so where a measurement crosses a level shows at a
// glance; drawn by the embedded curve_chart.py.
#pragma once

#include <string>
#include <vector>

namespace lab::plots {

struct Curve {
    std::string name;
    std::vector<double> x, y;  // as many of each, every one finite and > 0 (log axes)
    bool reference = false;    // a level to compare with, drawn dashed without markers
};

// csv_path may be empty; otherwise it gets one row per curve and point:  curve,kind,x,y (kind
// "measured" or "reference"). No curves, an empty curve, x and y of different lengths, a value that
// is not finite and > 0, or a name given twice is std::invalid_argument. Throws lab::InputError
// naming a path that cannot be written, std::runtime_error when no Python with matplotlib is found
// or the script fails.
void write_curve_chart(const std::vector<Curve>& curves, const std::string& x_label, const std::string& y_label, const std::string& title,
                       const std::string& png_path, const std::string& csv_path);

}  // namespace lab::plots
