// Directional albedo of a material against the incident angle, one validation estimate per angle.
#pragma once

#include <cstdint>
#include <vector>

#include "brdf/brdf.hpp"
#include "validation/albedo.hpp"

namespace lab::analysis {

struct AlbedoCurveOptions {
    int angles = 46;        // evenly spaced over [0, 90] degrees
    int strata = 64;        // strata x strata samples per angle (validation::directional_albedo)
    float phi_deg = 0.0f;   // azimuth of the incident direction (matters for anisotropic materials)
    uint64_t seed = 1;
};

struct AlbedoPoint {
    float theta_deg;
    validation::AlbedoEstimate estimate;
};

std::vector<AlbedoPoint> albedo_curve(const brdf::Material& m, const AlbedoCurveOptions& options = {});

}  // namespace lab::analysis
