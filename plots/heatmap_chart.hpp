// Heat maps side by side: one quantity over the same two-parameter grid for several methods (the
// stability atlas: a material's directional albedo over roughness and incident angle), coloured on a
// scale that diverges at `centre` (the value where nothing fails: an albedo of 1), so that where a
// method loses and where it creates show at a glance; when no value lies below the centre (a share
// of rays lost, 0 at best) only the scale's upper half, white at the centre; drawn by the embedded
// heatmap_chart.py.
#pragma once

#include <string>
#include <vector>

namespace lab::plots {

struct HeatmapPanel {
    std::string title;
    std::vector<double> values;  // x-major: values[i * y.size() + j] at (x[i], y[j])
};

// x, y: the grid's coordinates, increasing. Every panel holds x.size() * y.size() finite values, else
// std::invalid_argument (and for no panels or an empty axis). csv_path may be empty; otherwise it
// gets one row per panel and point:  panel,x,y,value. `log_x`: x on a logarithmic axis (a factor
// whose halving and doubling mean as much; x must then be > 0, else std::invalid_argument). Throws
// lab::InputError naming a path that cannot be written, std::runtime_error when no Python with
// matplotlib is found or the script fails.
void write_heatmap_chart(const std::vector<HeatmapPanel>& panels, const std::vector<double>& x, const std::vector<double>& y,
                         const std::string& x_label, const std::string& y_label, const std::string& value_label, double centre,
                         const std::string& title, const std::string& png_path, const std::string& csv_path, bool log_x = false);

}  // namespace lab::plots
