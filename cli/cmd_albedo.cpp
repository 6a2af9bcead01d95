// dtoadq albedo: directional albedo against incident angle, per channel, for one or more materials.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "common/input_error.hpp"
#include "plots/albedo_chart.hpp"
#include "plots/output_file.hpp"

namespace lab::cli {
namespace {

struct AlbedoOptions {
    std::vector<std::string> materials;
    std::string compensation = "preset";
    std::string png;
    std::string csv;
    double phi_in = 0.0;
    int angles = 46;
    int strata = 64;
    uint64_t seed = 1;
};

void run_albedo(const AlbedoOptions& o) {
    if (!std::isfinite(o.phi_in)) throw InputError("command line", "--phi-in", "must be a finite angle in degrees");
    if (o.angles < 2 || o.angles > 1000) throw InputError("command line", "--angles", "must be in [2, 1000]");
    if (o.strata < 1 || o.strata > 4096) throw InputError("command line", "--strata", "must be in [1, 4096]");
    plots::require_writable(o.png, "-o");
    if (!o.csv.empty()) plots::require_writable(o.csv, "--csv");
    std::vector<brdf::Preset> presets = with_compensation(load_presets(o.materials), o.compensation);
    analysis::AlbedoCurveOptions options;
    options.angles = o.angles;
    options.strata = o.strata;
    options.phi_deg = float(o.phi_in);
    options.seed = o.seed;
    plots::write_albedo_chart(presets, o.png, o.csv, options);
}

}  // namespace

void register_albedo(CLI::App& app) {
    auto options = std::make_shared<AlbedoOptions>();
    auto* cmd = app.add_subcommand("albedo", "Chart directional albedo against incident angle (r, g, b) to a PNG");
    cmd->add_option("--material", options->materials, "Material preset (JSON); repeat for several")->required();
    cmd->add_option("--compensation", options->compensation, kCompensationHelp)->capture_default_str();
    cmd->add_option("-o,--output", options->png, "PNG file to write")->required();
    cmd->add_option("--csv", options->csv, "Also write material,theta,a_r,a_g,a_b,se_r,se_g,se_b");
    cmd->add_option("--phi-in", options->phi_in, "Incident azimuth from the tangent, degrees")->capture_default_str();
    cmd->add_option("--angles", options->angles, "Incident angles, evenly spaced over [0, 90] degrees")->capture_default_str();
    cmd->add_option("--strata", options->strata, "Samples per angle: strata x strata, stratified")->capture_default_str();
    cmd->add_option("--seed", options->seed, "Random seed")->capture_default_str();
    cmd->callback([options] { run_albedo(*options); });
}

}  // namespace lab::cli
