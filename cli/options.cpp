#include "cli/options.hpp"

#include <cmath>
#include <sstream>

#include "common/input_error.hpp"

namespace lab::cli {

std::vector<brdf::Preset> load_presets(const std::vector<std::string>& paths) {
    std::vector<brdf::Preset> presets;
    for (const std::string& path : paths) presets.push_back(brdf::load_preset(path));
    return presets;
}

void parse_angle_pair(const std::string& text, const std::string& option, float* theta_deg, float* phi_deg) {
    std::istringstream in(text);
    double theta = 0.0, phi = 0.0;
    char comma = 0;
    if (!(in >> theta >> comma >> phi) || comma != ',' || !(in >> std::ws).eof())
        throw InputError("command line", option, "expected THETA,PHI in degrees, got \"" + text + "\"");
    if (!std::isfinite(theta) || !std::isfinite(phi)) throw InputError("command line", option, "angles must be finite");
    if (theta < 0.0 || theta > 180.0) throw InputError("command line", option, "theta must be in [0, 180] degrees");
    *theta_deg = float(theta);
    *phi_deg = float(phi);
}

brdf::float3 direction_from_degrees(float theta_deg, float phi_deg) {
    const double to_rad = M_PI / 180.0;
    double t = theta_deg * to_rad, p = phi_deg * to_rad;
    return brdf::float3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

void degrees_from_direction(brdf::float3 w, float* theta_deg, float* phi_deg) {
    const double to_deg = 180.0 / M_PI;
    *theta_deg = float(std::acos(std::fmin(std::fmax(double(w.z), -1.0), 1.0)) * to_deg);
    double phi = std::atan2(double(w.y), double(w.x)) * to_deg;
    *phi_deg = float(phi < 0.0 ? phi + 360.0 : phi);
}

}  // namespace lab::cli
