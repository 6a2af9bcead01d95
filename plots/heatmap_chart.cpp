#include "plots/heatmap_chart.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

void write_heatmap_chart(const std::vector<HeatmapPanel>& panels, const std::vector<double>& x, const std::vector<double>& y,
                         const std::string& x_label, const std::string& y_label, const std::string& value_label, double centre,
                         const std::string& title, const std::string& png_path, const std::string& csv_path, bool log_x) {
    if (panels.empty() || x.empty() || y.empty()) throw std::invalid_argument("heat map chart: no panels, or an empty axis");
    if (log_x)
        for (double v : x)
            if (!(v > 0.0)) throw std::invalid_argument("heat map chart: x = " + std::to_string(v) + " on a logarithmic axis");
    for (const HeatmapPanel& p : panels) {
        if (p.values.size() != x.size() * y.size())
            throw std::invalid_argument("heat map chart: panel \"" + p.title + "\" holds " + std::to_string(p.values.size()) + " values, not " +
                                        std::to_string(x.size() * y.size()));
        for (double v : p.values)
            if (!std::isfinite(v)) throw std::invalid_argument("heat map chart: panel \"" + p.title + "\" holds a value that is not finite");
    }
    char centre_text[32];
    std::snprintf(centre_text, sizeof centre_text, "%.7g", centre);
    std::vector<std::string> arguments = {"--title=" + title, "--x-label=" + x_label, "--y-label=" + y_label, "--value-label=" + value_label,
                                          "--centre", centre_text};
    if (log_x) arguments.push_back("--log-x");
    draw_chart("heatmap_chart.py", "panel,x,y,value",
               [&](std::ostream& out) {
                   char row[96];
                   for (const HeatmapPanel& p : panels)
                       for (size_t i = 0; i < x.size(); ++i)
                           for (size_t j = 0; j < y.size(); ++j) {
                               std::snprintf(row, sizeof row, ",%.7g,%.7g,%.7g\n", x[i], y[j], p.values[i * y.size() + j]);
                               out << csv_field(p.title) << row;
                           }
               },
               arguments, png_path, csv_path);
}

}  // namespace lab::plots
