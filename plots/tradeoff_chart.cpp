#include "plots/tradeoff_chart.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

void write_tradeoff_chart(const std::vector<TradeoffPoint>& points, double noise_level, const std::string& title, const std::string& error_label,
                          const std::string& png_path, const std::string& csv_path) {
    if (points.empty()) throw std::invalid_argument("trade-off chart: no points");
    for (const TradeoffPoint& p : points)
        if (!(p.seconds > 0.0) || !std::isfinite(p.seconds) || !(p.error >= 0.0) || !std::isfinite(p.error))
            throw std::invalid_argument("trade-off chart: point \"" + p.name + "\": time " + std::to_string(p.seconds) + " s, error " +
                                        std::to_string(p.error));
    if (!(noise_level >= 0.0) || !std::isfinite(noise_level)) throw std::invalid_argument("trade-off chart: noise level not finite and >= 0");
    char noise[32];
    std::snprintf(noise, sizeof noise, "%.7g", noise_level);
    draw_chart("tradeoff_chart.py", "setting,seconds,error",
               [&](std::ostream& out) {
                   char row[64];
                   for (const TradeoffPoint& p : points) {
                       std::snprintf(row, sizeof row, ",%.7g,%.7g\n", p.seconds, p.error);
                       out << csv_field(p.name) << row;
                   }
               },
               {"--title=" + title, "--error-label=" + error_label, "--noise", noise}, png_path, csv_path);
}

}  // namespace lab::plots
