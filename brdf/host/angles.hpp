// Directions of the local shading frame from angles in degrees and back: theta from the normal,
// phi from the tangent. The units every command line and chart of the lab speaks.
#pragma once

#include "brdf/brdf.hpp"

namespace brdf {

float3 direction_from_degrees(float theta_deg, float phi_deg);

// phi in [0, 360)
void degrees_from_direction(float3 w, float* theta_deg, float* phi_deg);

}  // namespace brdf
