#include "validation/energy.hpp"

#include <cmath>

#include "brdf/host/angles.hpp"
#include "validation/albedo.hpp"
#include "common/parallel_for.hpp"
#include "validation/sphere_quadrature.hpp"

namespace lab::validation {

namespace {

constexpr float kToDegrees = 180.0f / 3.14159265358979323846f;

}  // namespace

bool transmits(const brdf::Material& material) {
    brdf::Material m = brdf::material_clamped(&material);
    return m.model == BRDF_MODEL_LAB && brdf::lab_lobe_weights(&m).transmission > 0.0f;
}

std::vector<brdf::float3> furnace_directions(const brdf::Material& material, const FurnaceOptions& options) {
    brdf::Material m = brdf::material_clamped(&material);
    std::vector<float> phis{0.0f};
    if (m.anisotropic > 0.0f) phis = options.phis;
    std::vector<float> thetas = options.thetas;
    if (transmits(m))
        for (float t : options.thetas) thetas.push_back(180.0f - t);
    std::vector<brdf::float3> directions;
    for (float t : thetas)
        for (float p : phis) directions.push_back(brdf::direction_from_degrees(t, p + m.tangent_rotation * kToDegrees));
    return directions;
}

AlbedoPeak max_directional_albedo(const brdf::Material& material, const FurnaceOptions& options) {
    AlbedoPeak peak;
    peak.albedo = -1.0;
    float rotation_deg = brdf::material_clamped(&material).tangent_rotation * kToDegrees;
    auto undecided = [&](double value, double std_error) { return value + 3.0 * std_error > 1.0 + options.limit; };
    for (brdf::float3 wo : furnace_directions(material, options)) {
        int strata = options.strata;
        AlbedoEstimate a = directional_albedo(material, wo, strata, options.seed);
        auto any_undecided = [&]() {
            for (int c = 0; c < 3; ++c)
                if (undecided(a.value[c], a.std_error[c])) return true;
            return false;
        };
        while (any_undecided() && strata * 4 <= options.max_strata) {
            strata *= 4;
            a = directional_albedo(material, wo, strata, options.seed);
        }
        for (int c = 0; c < 3; ++c) {
            double value = a.value[c], std_error = a.std_error[c];
            int used_strata = strata;
            // An estimate decisively above the limit stands: whatever f integrates to, the sampler
            // then gains energy (its pdf is wrong somewhere), which is as much a failure.
            bool above = value - 3.0 * std_error > 1.0 + options.limit;
            if (undecided(value, std_error) && !above) {
                value = directional_albedo_quadrature(material, wo, c);
                std_error = 0.0;
                used_strata = 0;
            }
            if (value > peak.albedo) {
                peak.albedo = value;
                peak.std_error = std_error;
                peak.strata = used_strata;
                brdf::degrees_from_direction(wo, &peak.theta_deg, &peak.phi_deg);
                peak.phi_deg = std::remainder(peak.phi_deg - rotation_deg, 360.0f);
                if (std::fabs(peak.phi_deg) < 1e-3f) peak.phi_deg = 0.0f;
            }
        }
    }
    return peak;
}

FurnaceSweep furnace_sweep(const std::vector<brdf::Material>& materials, const FurnaceOptions& options, int threads) {
    FurnaceSweep sweep;
    sweep.peaks.resize(materials.size());
    parallel_for(int(materials.size()), threads,
                 [&](int i) { sweep.peaks[size_t(i)] = max_directional_albedo(materials[size_t(i)], options); });
    for (size_t i = 0; i < materials.size(); ++i)
        if (sweep.worst < 0 || sweep.peaks[i].albedo > sweep.peaks[size_t(sweep.worst)].albedo) sweep.worst = int(i);
    return sweep;
}

double delta_albedo(const brdf::Material& material, brdf::float3 wo, int channel, int strata) {
    double sum = 0.0;
    for (int i = 0; i < strata; ++i) {
        brdf::float3 u((float(i) + 0.5f) / float(strata), 0.5f, 0.5f);
        brdf::BsdfSample s = brdf::bsdf_sample(&material, wo, u);
        if ((s.flags & BSDF_DELTA) && s.pdf > 0.0f) sum += double(s.f[channel]) * std::fabs(s.wi.z) / s.pdf;
    }
    return sum / strata;
}

double directional_albedo_quadrature(const brdf::Material& material, brdf::float3 wo, int channel, double tolerance) {
    SphereGrid grid;
    QuadratureLimits limits;
    limits.max_depth = 8;  // bounds the cost of lobes sharper than the grid can resolve anyway
    auto f_cos = [&](int, brdf::float3 wi) { return double(brdf::bsdf_eval(&material, wo, wi)[channel]) * std::fabs(wi.z); };
    // relative to a one-point estimate of the cell's integral, with an absolute floor that sums to
    // a tenth of the tolerance over the sphere
    auto cell_tolerance = [&](int cell) {
        double z0, z1, p0, p1;
        grid.bounds(cell, &z0, &z1, &p0, &p1);
        double rough = f_cos(cell, direction_from_z_phi(0.5 * (z0 + z1), 0.5 * (p0 + p1))) * (z1 - z0) * (p1 - p0);
        return tolerance * rough + 0.1 * tolerance / grid.cells();
    };
    double sum = 0.0;
    for (double a : integrate_cells(f_cos, grid, cell_tolerance, 1, limits)) sum += a;
    return sum + delta_albedo(material, wo, channel);
}

}  // namespace lab::validation
