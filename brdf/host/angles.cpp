#include "brdf/host/angles.hpp"

#include <cmath>

namespace brdf {

float3 direction_from_degrees(float theta_deg, float phi_deg) {
    const double to_rad = M_PI / 180.0;
    double t = theta_deg * to_rad, p = phi_deg * to_rad;
    return float3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

void degrees_from_direction(float3 w, float* theta_deg, float* phi_deg) {
    const double to_deg = 180.0 / M_PI;
    *theta_deg = float(std::acos(std::fmin(std::fmax(double(w.z), -1.0), 1.0)) * to_deg);
    double phi = std::atan2(double(w.y), double(w.x)) * to_deg;
    *phi_deg = float(phi < 0.0 ? phi + 360.0 : phi);
}

}  // namespace brdf
