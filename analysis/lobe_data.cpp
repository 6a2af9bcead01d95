#include "analysis/lobe_data.hpp"

#include <cmath>
#include <stdexcept>

#include "brdf/host/angles.hpp"
#include "analysis/luminance.hpp"

namespace lab::analysis {

using brdf::degrees_from_direction;
using brdf::direction_from_degrees;

namespace {

// Steps that must split [0, 90] evenly, so 90 degrees (the horizon) is always a sample.
int steps_in_90(float step_deg) {
    if (!is_lobe_grid_step(step_deg))
        throw std::invalid_argument("lobe resolution " + std::to_string(step_deg) + " degrees does not divide 90");
    return int(std::lround(90.0 / step_deg));
}

// Direction of the plane-of-incidence slice at a signed angle from the normal (see PlaneSample).
brdf::float3 plane_direction(float angle_deg, float phi_in_deg) {
    return direction_from_degrees(std::fabs(angle_deg), angle_deg >= 0.0f ? phi_in_deg + 180.0f : phi_in_deg);
}

}  // namespace

bool is_lobe_grid_step(float step_deg) {
    double n = 90.0 / step_deg;
    return step_deg > 0.0f && n >= 1.0 && n <= 10000.0 && std::fabs(n - std::round(n)) < 1e-4;
}

std::vector<DeltaLobe> find_delta_lobes(const brdf::Material& m, float theta_in_deg, float phi_in_deg) {
    // Every sampler picks its lobe with u.x. Sweeping u.x over a fine stratified grid and summing
    // f |cos| / pdf of the delta samples per direction gives each delta direction's albedo share,
    // including several lobes (mirror + smooth dielectric) that share one direction.
    const int n = 4096;
    brdf::float3 wi = direction_from_degrees(theta_in_deg, phi_in_deg);
    brdf::float3 mirror_side = direction_from_degrees(90.0f, phi_in_deg + 180.0f);
    brdf::float3 normal_to_plane = brdf::cross(brdf::float3(0.0f, 0.0f, 1.0f), mirror_side);
    std::vector<DeltaLobe> lobes;
    std::vector<brdf::float3> directions;
    for (int k = 0; k < n; ++k) {
        brdf::float3 u((float(k) + 0.5f) / float(n), 0.5f, 0.5f);
        brdf::BsdfSample s = brdf::bsdf_sample(&m, wi, u);
        if (!(s.flags & BSDF_DELTA) || !(s.pdf > 0.0f)) continue;
        brdf::float3 share = s.f * (std::fabs(s.wi.z) / (s.pdf * float(n)));
        size_t i = 0;
        while (i < directions.size() && brdf::dot(directions[i], s.wi) < 1.0f - 1e-6f) ++i;
        if (i == directions.size()) {
            DeltaLobe lobe{};
            degrees_from_direction(s.wi, &lobe.theta_deg, &lobe.phi_deg);
            lobe.plane_angle_deg = float(std::atan2(brdf::dot(s.wi, mirror_side), s.wi.z) * 180.0 / M_PI);
            if (lobe.plane_angle_deg <= -180.0f) lobe.plane_angle_deg = 180.0f;  // straight down: atan2 of -0
            lobe.in_plane = std::fabs(brdf::dot(s.wi, normal_to_plane)) < 1e-3f;
            lobe.transmission = (s.flags & BSDF_TRANSMISSION) != 0;
            lobe.weight = brdf::float3(0.0f);
            lobes.push_back(lobe);
            directions.push_back(s.wi);
        }
        lobes[i].weight += share;
    }
    return lobes;
}

LobeData compute_lobe(const brdf::Preset& preset, float theta_in_deg, float phi_in_deg, const LobeResolution& resolution) {
    const brdf::Material& m = preset.material;
    brdf::float3 wi = direction_from_degrees(theta_in_deg, phi_in_deg);
    LobeData data;
    data.material = preset.name;
    data.deltas = find_delta_lobes(m, theta_in_deg, phi_in_deg);

    // the whole sphere first; the lower rows are dropped again for a material that does not transmit
    const float step = resolution.grid_theta_step_deg;
    const int half = steps_in_90(step);
    data.theta_count = 2 * half + 1;
    data.phi_count = 2 * half;  // phi step 2 * step over [0, 360)
    for (int t = 0; t < data.theta_count; ++t) {
        float theta = float(t) * 90.0f / float(half);
        for (int p = 0; p < data.phi_count; ++p) {
            float phi = float(p) * 360.0f / float(data.phi_count);
            brdf::float3 wo = direction_from_degrees(theta, phi);
            LobeSample s{theta, phi, brdf::bsdf_eval(&m, wi, wo), brdf::bsdf_pdf(&m, wi, wo)};
            if (theta > 90.0f && (s.f.x > 0.0f || s.f.y > 0.0f || s.f.z > 0.0f)) data.transmits = true;
            data.grid.push_back(s);
        }
    }
    for (const DeltaLobe& d : data.deltas) data.transmits |= d.transmission;
    if (!data.transmits) {
        data.theta_count = half + 1;
        data.grid.resize(size_t(data.theta_count) * size_t(data.phi_count));
    }

    data.plane = plane_slice([&m](brdf::float3 in, brdf::float3 out) { return brdf::bsdf_eval(&m, in, out); }, theta_in_deg,
                             phi_in_deg, resolution.plane_step_deg, data.transmits);
    return data;
}

std::vector<PlaneSample> plane_slice(const BsdfFunction& f, float theta_in_deg, float phi_in_deg, float step_deg, bool below) {
    const brdf::float3 wi = direction_from_degrees(theta_in_deg, phi_in_deg);
    const int plane_half = steps_in_90(step_deg);
    const int extent = below ? 2 * plane_half : plane_half;
    std::vector<PlaneSample> plane;
    for (int k = -extent; k <= extent; ++k) {
        float angle = float(k) * 90.0f / float(plane_half);
        brdf::float3 wo = plane_direction(angle, phi_in_deg);
        plane.push_back({angle, luminance(f(wi, wo)) * std::fabs(wo.z)});
    }
    return plane;
}

}  // namespace lab::analysis
