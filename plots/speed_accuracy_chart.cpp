#include "plots/speed_accuracy_chart.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

namespace {

void check_series(const std::vector<ConvergenceSeries>& series) {
    if (series.empty()) throw std::invalid_argument("speed-accuracy chart: no series");
    for (const ConvergenceSeries& s : series) {
        const std::string where = "speed-accuracy chart: series \"" + s.name + "\"";
        if (s.seconds.empty()) throw std::invalid_argument(where + " has no points");
        if (s.seconds.size() != s.rmse.size())
            throw std::invalid_argument(where + " has " + std::to_string(s.seconds.size()) + " times and " + std::to_string(s.rmse.size()) +
                                        " errors");
        for (size_t i = 0; i < s.seconds.size(); ++i)
            if (!(s.seconds[i] > 0.0) || !(s.rmse[i] > 0.0) || !std::isfinite(s.seconds[i]) || !std::isfinite(s.rmse[i]))
                throw std::invalid_argument(where + ", point " + std::to_string(i) + ": time " + std::to_string(s.seconds[i]) + " s, error " +
                                            std::to_string(s.rmse[i]) + " (a log axis needs finite positive values)");
    }
}

void write_table(const std::vector<ConvergenceSeries>& series, const std::string& path) {
    std::ofstream out = open_output(path, "");
    out << "series,seconds,rmse\n";
    char row[64];
    for (const ConvergenceSeries& s : series)
        for (size_t i = 0; i < s.seconds.size(); ++i) {
            std::snprintf(row, sizeof row, ",%.7g,%.7g\n", s.seconds[i], s.rmse[i]);
            out << csv_field(s.name) << row;
        }
    if (!out.flush()) throw InputError(path, "", "write failed");
}

}  // namespace

void write_speed_accuracy_chart(const std::vector<ConvergenceSeries>& series, const std::string& title, const std::string& png_path,
                                const std::string& csv_path, const std::string& error_label) {
    check_series(series);
    require_writable(png_path, "");
    if (!csv_path.empty()) require_writable(csv_path, "");

    TempFolder folder("plot");
    const fs::path csv = folder.path() / "speed_accuracy.csv";
    const fs::path png = folder.path() / "speed_accuracy.png";
    write_table(series, csv.string());
    run_plot_script("speed_accuracy_chart.py", {"--data", csv.string(), "--out", png.string(), "--title=" + title, "--error-label=" + error_label}, folder.path());
    if (!csv_path.empty()) install_output(csv, csv_path, "");
    install_output(png, png_path, "");
}

}  // namespace lab::plots
