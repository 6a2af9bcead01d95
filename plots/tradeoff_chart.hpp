// Time against error of settings that trade one for the other (sphere tracing's over-relaxation,
// the normal estimator): one labelled point per setting, the time of one sample per pixel on the x
// axis and the error the setting causes on the y axis, with the level below which an error cannot
// be told from noise drawn as a band; drawn by the embedded tradeoff_chart.py.
#pragma once

#include <string>
#include <vector>

namespace lab::plots {

struct TradeoffPoint {
    std::string name;
    double seconds = 0.0;  // per sample per pixel
    double error = 0.0;    // what the setting causes, >= 0
};

// `noise_level`: the error below which a difference is noise (the band), >= 0. csv_path may be
// empty; otherwise it gets one row per point:  setting,seconds,error. Points with a time that is not
// finite and positive, or an error that is not finite and non-negative, and an empty list, are
// std::invalid_argument. Throws lab::InputError naming a path that cannot be written,
// std::runtime_error when no Python with matplotlib is found or the script fails.
void write_tradeoff_chart(const std::vector<TradeoffPoint>& points, double noise_level, const std::string& title, const std::string& error_label,
                          const std::string& png_path, const std::string& csv_path);

}  // namespace lab::plots
