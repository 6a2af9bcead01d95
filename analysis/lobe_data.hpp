// The numbers behind a lobe plot: a material's BSDF for one incident direction, sampled over a
// grid of outgoing directions, along the plane of incidence, and its delta lobes.
// Convention (as `dtoadq brdf eval`): the user's incident direction wi is the BSDF's first,
// conditioning argument; values are f(wi, wo) and pdf(wi, wo) as functions of wo.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/preset.hpp"

namespace lab::analysis {

struct LobeSample {
    float theta_deg, phi_deg;  // of wo: theta from the normal (> 90 below the surface), phi in [0, 360)
    brdf::float3 f;
    float pdf;
};

// A point of the slice through the plane of incidence. angle_deg is the signed angle of wo from the
// normal, positive towards the mirror side (phi_in + 180), in [-180, 180]; |angle| > 90 is below.
struct PlaneSample {
    float angle_deg;
    float value;  // luminance of f(wi, wo) |cos theta_o|
};

// A delta lobe cannot be drawn as a function; its weight is the share of the incident light it
// carries (its term of the directional albedo).
struct DeltaLobe {
    float theta_deg, phi_deg;
    float plane_angle_deg;  // as PlaneSample::angle_deg
    bool in_plane;          // false when it leaves the plane of incidence
    bool transmission;
    brdf::float3 weight;
};

struct LobeData {
    std::string material;
    bool transmits = false;           // some light goes below the surface (rough or delta)
    std::vector<LobeSample> grid;     // theta rows x phi columns; rows to 180 when it transmits
    int theta_count = 0, phi_count = 0;
    std::vector<PlaneSample> plane;   // to +-180 when it transmits, else +-90
    std::vector<DeltaLobe> deltas;
};

struct LobeResolution {
    float grid_theta_step_deg = 1.0f;  // the phi step is twice this; must divide 90
    float plane_step_deg = 0.25f;
};

// True when step_deg splits [0, 90] into whole steps, as a grid step must.
bool is_lobe_grid_step(float step_deg);

// The slice through the plane of incidence of any BSDF f(wi, wo) (a material's, or a measured
// table's): luminance of f |cos theta_o| every step_deg (which must divide 90), over the upper half
// (+-90) or, with below, the whole circle (+-180).
using BsdfFunction = std::function<brdf::float3(brdf::float3 wi, brdf::float3 wo)>;
std::vector<PlaneSample> plane_slice(const BsdfFunction& f, float theta_in_deg, float phi_in_deg, float step_deg, bool below);

LobeData compute_lobe(const brdf::Preset& preset, float theta_in_deg, float phi_in_deg, const LobeResolution& resolution);

// Delta lobes for incident direction wi, found by sweeping the sampler's lobe choice.
std::vector<DeltaLobe> find_delta_lobes(const brdf::Material& m, float theta_in_deg, float phi_in_deg);

}  // namespace lab::analysis
