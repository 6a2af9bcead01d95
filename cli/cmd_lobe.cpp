// dtoadq lobe: polar and 3D lobe plots of one or more materials for one incident direction.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "analysis/lobe_data.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "common/input_error.hpp"
#include "plots/lobe_plot.hpp"
#include "plots/output_file.hpp"

namespace lab::cli {
namespace {

struct LobeOptions {
    std::vector<std::string> materials;
    std::string compensation = "preset";
    double theta_in = 0.0;
    double phi_in = 0.0;
    std::string png;
    std::string csv;
    double resolution = 1.0;
    std::string scale = "auto";
};

void run_lobe(const LobeOptions& o) {
    if (!std::isfinite(o.theta_in) || o.theta_in < 0.0 || o.theta_in >= 90.0)
        throw InputError("command line", "--theta-in", "must be in [0, 90) degrees");
    if (!std::isfinite(o.phi_in)) throw InputError("command line", "--phi-in", "must be a finite angle in degrees");
    if (!(o.resolution >= 0.1 && o.resolution <= 30.0) || !analysis::is_lobe_grid_step(float(o.resolution)))
        throw InputError("command line", "--resolution", "must divide 90 and lie in [0.1, 30] degrees");
    if (o.scale != "auto" && o.scale != "linear" && o.scale != "log")
        throw InputError("command line", "--scale", "expected auto, linear or log, got \"" + o.scale + "\"");
    // fail on a bad output path before loading and computing anything
    plots::require_writable(o.png, "-o");
    if (!o.csv.empty()) plots::require_writable(o.csv, "--csv");
    std::vector<brdf::Preset> presets = with_compensation(load_presets(o.materials), o.compensation);
    plots::LobePlotOptions options;
    options.csv_theta_step_deg = float(o.resolution);
    options.scale = o.scale == "log" ? plots::RadialScale::log : o.scale == "linear" ? plots::RadialScale::linear : plots::RadialScale::automatic;
    plots::write_lobe_plot(presets, float(o.theta_in), float(o.phi_in), o.png, o.csv, options);
}

}  // namespace

void register_lobe(CLI::App& app) {
    auto options = std::make_shared<LobeOptions>();
    auto* cmd = app.add_subcommand("lobe", "Plot BSDF lobes (plane-of-incidence polar view and 3D view) to a PNG");
    cmd->add_option("--material", options->materials, "Material preset (JSON); repeat to overlay several")->required();
    cmd->add_option("--compensation", options->compensation, kCompensationHelp)->capture_default_str();
    cmd->add_option("--theta-in", options->theta_in, "Incident angle from the normal, degrees in [0, 90)")->required();
    cmd->add_option("--phi-in", options->phi_in, "Incident azimuth from the tangent, degrees")->capture_default_str();
    cmd->add_option("-o,--output", options->png, "PNG file to write")->required();
    cmd->add_option("--csv", options->csv, "Also write material,theta_o,phi_o,f_r,f_g,f_b,pdf over a grid of outgoing directions");
    cmd->add_option("--resolution", options->resolution, "Theta step of the --csv grid in degrees (phi step is twice it)")
        ->capture_default_str();
    cmd->add_option("--scale", options->scale, "Radial scale: auto (log when the peaks differ by more than 20x), linear or log")
        ->capture_default_str();
    cmd->callback([options] { run_lobe(*options); });
}

}  // namespace lab::cli
