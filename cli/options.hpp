// Pieces the subcommands share: loading the --material presets and reading angle pairs.
#pragma once

#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/preset.hpp"

namespace lab::cli {

std::vector<brdf::Preset> load_presets(const std::vector<std::string>& paths);

// "THETA,PHI" in degrees; `option` names the flag in the error message.
void parse_angle_pair(const std::string& text, const std::string& option, float* theta_deg, float* phi_deg);

// Local-frame direction from angles in degrees: theta from the normal, phi from the tangent.
brdf::float3 direction_from_degrees(float theta_deg, float phi_deg);
void degrees_from_direction(brdf::float3 w, float* theta_deg, float* phi_deg);

}  // namespace lab::cli
