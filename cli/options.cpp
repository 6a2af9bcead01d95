#include "cli/options.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/input_error.hpp"

namespace lab::cli {

std::vector<brdf::Preset> load_presets(const std::vector<std::string>& paths) {
    std::vector<brdf::Preset> presets;
    for (const std::string& path : paths) presets.push_back(brdf::load_preset(path));
    return presets;
}

std::vector<brdf::Preset> with_compensation(const std::vector<brdf::Preset>& presets, const std::string& mode) {
    if (mode != "preset" && mode != "on" && mode != "off" && mode != "both")
        throw InputError("command line", "--compensation", "expected preset, on, off or both, got \"" + mode + "\"");
    if (mode == "preset") return presets;
    std::vector<brdf::Preset> out;
    for (const brdf::Preset& p : presets) {
        for (int on : {1, 0}) {
            if ((mode == "on" && !on) || (mode == "off" && on)) continue;
            brdf::Preset copy = p;
            copy.material.energy_compensation = on;
            if (mode == "both" && p.material.model == BRDF_MODEL_LAB) copy.name += on ? " (compensated)" : " (single scattering)";
            out.push_back(copy);
            if (mode == "both" && p.material.model != BRDF_MODEL_LAB) break;  // the 2017 model has no such switch
        }
    }
    return out;
}

std::vector<brdf::Preset> load_preset_folder(const std::string& folder, const std::string& option) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        throw InputError(folder, option, "not a folder of presets (run from the repository root or pass " + option + " DIR)");
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
    if (paths.empty()) throw InputError(folder, option, "holds no .json preset");
    std::sort(paths.begin(), paths.end());
    return load_presets(paths);
}

void parse_angle_pair(const std::string& text, const std::string& option, float* theta_deg, float* phi_deg) {
    std::istringstream in(text);
    double theta = 0.0, phi = 0.0;
    char comma = 0;
    if (!(in >> theta >> comma >> phi) || comma != ',' || !(in >> std::ws).eof())
        throw InputError("command line", option, "expected THETA,PHI in degrees, got \"" + text + "\"");
    // finite as the floats they become: 1e300 is a finite double but an infinite float
    if (!std::isfinite(float(theta)) || !std::isfinite(float(phi))) throw InputError("command line", option, "angles must be finite");
    if (theta < 0.0 || theta > 180.0) throw InputError("command line", option, "theta must be in [0, 180] degrees");
    *theta_deg = float(theta);
    *phi_deg = float(phi);
}

}  // namespace lab::cli
