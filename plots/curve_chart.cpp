#include "plots/curve_chart.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

void write_curve_chart(const std::vector<Curve>& curves, const std::string& x_label, const std::string& y_label, const std::string& title,
                       const std::string& png_path, const std::string& csv_path) {
    if (curves.empty()) throw std::invalid_argument("curve chart: no curves");
    std::set<std::string> names;
    for (const Curve& c : curves) {
        if (!names.insert(c.name).second) throw std::invalid_argument("curve chart: curve \"" + c.name + "\" is given twice");
        if (c.x.empty() || c.x.size() != c.y.size())
            throw std::invalid_argument("curve chart: curve \"" + c.name + "\" has " + std::to_string(c.x.size()) + " x and " +
                                        std::to_string(c.y.size()) + " y values");
        for (const std::vector<double>* values : {&c.x, &c.y})
            for (double v : *values)
                if (!(v > 0.0) || !std::isfinite(v))
                    throw std::invalid_argument("curve chart: curve \"" + c.name + "\" holds " + std::to_string(v) + ", not finite and > 0 (log axes)");
    }
    draw_chart("curve_chart.py", "curve,kind,x,y",
               [&](std::ostream& out) {
                   char row[80];
                   for (const Curve& c : curves)
                       for (size_t i = 0; i < c.x.size(); ++i) {
                           std::snprintf(row, sizeof row, ",%s,%.7g,%.7g\n", c.reference ? "reference" : "measured", c.x[i], c.y[i]);
                           out << csv_field(c.name) << row;
                       }
               },
               {"--title=" + title, "--x-label=" + x_label, "--y-label=" + y_label}, png_path, csv_path);
}

}  // namespace lab::plots
