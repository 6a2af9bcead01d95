#include "plots/lobe_plot.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/child_process.hpp"
#include "analysis/lobe_data.hpp"
#include "analysis/luminance.hpp"
#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

namespace {

// Fine enough along the plane for the sharpest glossy lobes; coarse enough for matplotlib's 3D.
constexpr analysis::LobeResolution kPlotResolution{1.0f, 0.1f};

void check_incidence(float theta_in_deg, float phi_in_deg) {
    if (!(theta_in_deg >= 0.0f && theta_in_deg < 90.0f) || !std::isfinite(phi_in_deg))
        throw std::invalid_argument("lobe plot: the incident direction must have theta in [0, 90) and a finite phi");
}

void write_plot_data(const std::vector<analysis::LobeData>& lobes, const fs::path& folder) {
    std::ofstream materials = open_output((folder / "materials.csv").string(), "");
    std::ofstream plane = open_output((folder / "plane.csv").string(), "");
    std::ofstream surface = open_output((folder / "surface.csv").string(), "");
    std::ofstream deltas = open_output((folder / "deltas.csv").string(), "");
    materials << "material,name,transmits\n";
    plane << "material,angle_deg,value\n";
    surface << "material,theta_deg,phi_deg,value\n";
    deltas << "material,theta_deg,phi_deg,plane_angle_deg,in_plane,transmission,w_r,w_g,w_b\n";
    for (size_t i = 0; i < lobes.size(); ++i) {
        const analysis::LobeData& d = lobes[i];
        materials << i << "," << csv_field(d.material) << "," << int(d.transmits) << "\n";
        for (const analysis::PlaneSample& s : d.plane) plane << i << "," << csv_number(s.angle_deg) << "," << csv_number(s.value) << "\n";
        for (const analysis::LobeSample& s : d.grid) {
            double value = analysis::luminance(s.f) * std::fabs(std::cos(double(s.theta_deg) * M_PI / 180.0));
            surface << i << "," << csv_number(s.theta_deg) << "," << csv_number(s.phi_deg) << "," << csv_number(value) << "\n";
        }
        for (const analysis::DeltaLobe& l : d.deltas)
            deltas << i << "," << csv_number(l.theta_deg) << "," << csv_number(l.phi_deg) << "," << csv_number(l.plane_angle_deg) << ","
                   << int(l.in_plane) << "," << int(l.transmission) << "," << csv_number(l.weight.x) << "," << csv_number(l.weight.y) << ","
                   << csv_number(l.weight.z) << "\n";
    }
    for (std::ofstream* f : {&materials, &plane, &surface, &deltas})
        if (!f->flush()) throw std::runtime_error("cannot write plot data in " + folder.string());
}

}  // namespace

void write_lobe_csv(const std::vector<brdf::Preset>& presets, float theta_in_deg, float phi_in_deg, const std::string& csv_path,
                    float theta_step_deg) {
    check_incidence(theta_in_deg, phi_in_deg);
    std::ofstream out = open_output(csv_path, "");
    out << "material,theta_o,phi_o,f_r,f_g,f_b,pdf\n";
    for (const brdf::Preset& p : presets) {
        analysis::LobeData d = analysis::compute_lobe(p, theta_in_deg, phi_in_deg, analysis::LobeResolution{theta_step_deg, kPlotResolution.plane_step_deg});
        std::string name = csv_field(d.material);
        for (const analysis::LobeSample& s : d.grid)
            out << name << "," << csv_number(s.theta_deg) << "," << csv_number(s.phi_deg) << "," << csv_number(s.f.x) << "," << csv_number(s.f.y) << ","
                << csv_number(s.f.z) << "," << csv_number(s.pdf) << "\n";
    }
    if (!out.flush()) throw InputError(csv_path, "", "write failed");
}

void write_lobe_plot(const std::vector<brdf::Preset>& presets, float theta_in_deg, float phi_in_deg, const std::string& png_path,
                     const std::string& csv_path, const LobePlotOptions& options) {
    check_incidence(theta_in_deg, phi_in_deg);
    if (presets.empty()) throw std::invalid_argument("lobe plot: no materials");
    require_writable(png_path, "");
    if (!csv_path.empty()) require_writable(csv_path, "");

    std::vector<analysis::LobeData> lobes;
    for (const brdf::Preset& p : presets) lobes.push_back(analysis::compute_lobe(p, theta_in_deg, phi_in_deg, kPlotResolution));
    TempFolder folder("plot");
    write_plot_data(lobes, folder.path());
    fs::path png = folder.path() / "lobe.png";
    std::vector<std::string> args = {"--data", folder.path().string(), "--out", png.string(), "--theta-in", csv_number(theta_in_deg),
                                     "--phi-in", csv_number(phi_in_deg)};
    args.push_back("--scale");
    args.push_back(options.scale == RadialScale::log ? "log" : options.scale == RadialScale::linear ? "linear" : "auto");
    run_plot_script("lobe_plot.py", args, folder.path());
    if (!csv_path.empty()) write_lobe_csv(presets, theta_in_deg, phi_in_deg, csv_path, options.csv_theta_step_deg);
    install_output(png, png_path, "");
}

}  // namespace lab::plots
