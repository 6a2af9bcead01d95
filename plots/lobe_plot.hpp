// Lobe plots as PNG: the plane-of-incidence polar slice and the 3D lobe of several materials,
// overlaid, drawn by the embedded lobe_plot.py with matplotlib.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/preset.hpp"

namespace lab::plots {

// The polar and 3D radius: automatic is log when the materials' peaks differ by more than 20x.
enum class RadialScale { automatic, linear, log };

struct LobePlotOptions {
    float csv_theta_step_deg = 1.0f;  // resolution of the --csv grid (phi step twice this); divides 90
    RadialScale scale = RadialScale::automatic;
};

// theta_in_deg in [0, 90), phi_in_deg finite: the incident direction, the BSDF's first argument.
// csv_path may be empty; otherwise it gets one row per material and grid direction:
//   material,theta_o,phi_o,f_r,f_g,f_b,pdf  (theta_o to 180 for materials that transmit).
// Throws lab::InputError naming a path that cannot be written, std::runtime_error when no Python
// with matplotlib is found or the script fails.
void write_lobe_plot(const std::vector<brdf::Preset>& presets, float theta_in_deg, float phi_in_deg, const std::string& png_path,
                     const std::string& csv_path, const LobePlotOptions& options = {});

// The --csv table alone.
void write_lobe_csv(const std::vector<brdf::Preset>& presets, float theta_in_deg, float phi_in_deg, const std::string& csv_path,
                    float theta_step_deg);

}  // namespace lab::plots
