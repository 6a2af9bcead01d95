#include "plots/albedo_chart.hpp"

#include <cstdio>
#include <stdexcept>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

namespace {

void write_table(const std::vector<brdf::Preset>& presets, const std::vector<std::vector<analysis::AlbedoPoint>>& curves, const std::string& path,
                 const std::string& field) {
    std::ofstream out = open_output(path, field);
    out << "material,theta,a_r,a_g,a_b,se_r,se_g,se_b\n";
    char row[256];
    for (size_t i = 0; i < presets.size(); ++i) {
        for (const analysis::AlbedoPoint& p : curves[i]) {
            const validation::AlbedoEstimate& e = p.estimate;
            std::snprintf(row, sizeof row, ",%.7g,%.7g,%.7g,%.7g,%.4g,%.4g,%.4g\n", p.theta_deg, e.value.x, e.value.y, e.value.z,
                          e.std_error.x, e.std_error.y, e.std_error.z);
            out << csv_field(presets[i].name) << row;
        }
    }
    if (!out.flush()) throw InputError(path, field, "write failed");
}

}  // namespace

void write_albedo_chart(const std::vector<brdf::Preset>& presets, const std::string& png_path, const std::string& csv_path,
                        const analysis::AlbedoCurveOptions& options) {
    if (presets.empty()) throw std::invalid_argument("albedo chart: no materials");
    require_writable(png_path, "");
    if (!csv_path.empty()) require_writable(csv_path, "");
    std::vector<std::vector<analysis::AlbedoPoint>> curves;
    for (const brdf::Preset& p : presets) curves.push_back(analysis::albedo_curve(p.material, options));
    write_albedo_chart(presets, curves, png_path, csv_path, options);
}

void write_albedo_chart(const std::vector<brdf::Preset>& presets, const std::vector<std::vector<analysis::AlbedoPoint>>& curves,
                        const std::string& png_path, const std::string& csv_path, const analysis::AlbedoCurveOptions& options) {
    if (presets.empty() || curves.size() != presets.size()) throw std::invalid_argument("albedo chart: no materials, or not one curve each");
    require_writable(png_path, "");
    if (!csv_path.empty()) require_writable(csv_path, "");
    TempFolder folder("plot");
    write_table(presets, curves, (folder.path() / "albedo.csv").string(), "");
    fs::path png = folder.path() / "albedo.png";
    char phi[32];
    std::snprintf(phi, sizeof phi, "%g", options.phi_deg);
    run_plot_script("albedo_chart.py",
                    {"--data", (folder.path() / "albedo.csv").string(), "--out", png.string(), "--phi-in", phi, "--samples",
                     std::to_string(long(options.strata) * options.strata)},
                    folder.path());
    if (!csv_path.empty()) install_output(folder.path() / "albedo.csv", csv_path, "");
    install_output(png, png_path, "");
}

}  // namespace lab::plots
