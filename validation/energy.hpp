// White-furnace checks: the directional albedo of a BSDF (validation/albedo.hpp) must not exceed 1
// at any incident direction, grazing ones included, from both sides of a transmissive surface.
#pragma once

#include <cstdint>
#include <vector>

#include "brdf/brdf.hpp"

namespace lab::validation {

struct FurnaceOptions {
    // Polar angles of wo in degrees; for a transmissive material they are also used from inside
    // (180 - theta). 89.9 is the grazing case where masking terms usually break.
    std::vector<float> thetas{0.0f, 15.0f, 30.0f, 45.0f, 60.0f, 70.0f, 80.0f, 85.0f, 88.0f, 89.9f};
    // Azimuths in degrees from the (rotated) tangent, used for anisotropic materials; by symmetry
    // of the stretched distribution a quarter turn covers all.
    std::vector<float> phis{0.0f, 30.0f, 60.0f, 90.0f};
    int strata = 128;  // the albedo estimator's strata x strata samples per direction
    uint64_t seed = 1;
    // An estimate whose verdict against 1 + limit is not clear at 3 standard errors is redone with
    // 4x the strata, up to max_strata, then by quadrature (directional_albedo_quadrature below);
    // one decisively above the limit is kept, as the sampler then gains energy.
    double limit = 1e-3;
    int max_strata = 1024;
};

struct AlbedoPeak {
    double albedo = 0.0;      // largest channel at the worst direction
    double std_error = 0.0;   // its estimator's standard error
    float theta_deg = 0.0f;   // > 90: incident from inside
    float phi_deg = 0.0f;     // in the material's unrotated frame
    int strata = 0;           // of the estimate kept; 0 when it came from quadrature
};

// Whether light can reach the lower side, so the furnace must also be run from inside.
bool transmits(const brdf::Material& material);

// The incident directions the furnace visits for this material.
std::vector<brdf::float3> furnace_directions(const brdf::Material& material, const FurnaceOptions& options);

AlbedoPeak max_directional_albedo(const brdf::Material& material, const FurnaceOptions& options);

struct FurnaceSweep {
    std::vector<AlbedoPeak> peaks;  // one per material
    int worst = -1;                 // index of the largest albedo
};

// max_directional_albedo for each material, on `threads` threads.
FurnaceSweep furnace_sweep(const std::vector<brdf::Material>& materials, const FurnaceOptions& options, int threads = 2);

// The part of the albedo carried by delta lobes: their sample weights depend on u.x only (lobe and
// Fresnel choice), so a midpoint rule over u.x is exact up to 1 / strata at each lobe boundary.
double delta_albedo(const brdf::Material& material, brdf::float3 wo, int channel = 0, int strata = 1 << 16);

// The albedo by adaptive quadrature of f(wo, wi) |cos theta_i| over the cells of a SphereGrid, plus
// delta_albedo(). No sampler is involved: it stands in for the estimator where importance sampling
// leaves heavy-tailed weights (Hyper-Cauchy normals at grazing incidence, sharp Henyey-Greenstein
// lobes). Lobes narrower than a cell (about 2 degrees) are found by refinement only, at a cost.
double directional_albedo_quadrature(const brdf::Material& material, brdf::float3 wo, int channel = 0,
                                     double tolerance = 1e-4);

}  // namespace lab::validation
