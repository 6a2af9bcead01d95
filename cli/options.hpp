// Pieces the subcommands share: loading the --material presets and reading angle pairs.
#pragma once

#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/preset.hpp"

namespace lab::cli {

std::vector<brdf::Preset> load_presets(const std::vector<std::string>& paths);

// --compensation: "preset" keeps each preset's energy_compensation, "on" / "off" force it, "both"
// shows each lab-model preset twice, compensated and single-scattering, named accordingly.
std::vector<brdf::Preset> with_compensation(const std::vector<brdf::Preset>& presets, const std::string& mode);
inline constexpr const char* kCompensationHelp =
    "Energy compensation: preset (as each file says), on, off, or both (each material compensated and single-scattering)";

// Every *.json preset in a folder, sorted by file name; `option` names the flag in errors.
std::vector<brdf::Preset> load_preset_folder(const std::string& folder, const std::string& option);

// "THETA,PHI" in degrees; `option` names the flag in the error message.
void parse_angle_pair(const std::string& text, const std::string& option, float* theta_deg, float* phi_deg);

using brdf::degrees_from_direction;
using brdf::direction_from_degrees;

}  // namespace lab::cli
