#include "validation/random_inputs.hpp"

#include <cmath>
#include <string>

#include "brdf/host/parameters.hpp"

namespace lab::validation {

namespace {

float draw(UniformRandom& rng, float lo, float hi, float edge_probability) {
    if (edge_probability > 0.0f && rng.next_float() < edge_probability) return rng.next_float() < 0.5f ? lo : hi;
    return rng.uniform(lo, hi);
}

}  // namespace

brdf::Material random_edge_material(UniformRandom& rng, int model, float edge_probability) {
    if (model == BRDF_MODEL_OPENPBR) {  // OpenPBR's inputs over their ranges, colours per channel
        brdf::Material m = brdf::default_material(model);
        for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
            // the emission is no part of the BSDF these materials test (it has checks of its own):
            // drawing it would only move every later draw
            if (std::string(p.group) == "emission") continue;
            if (p.field) m.*p.field = draw(rng, p.min, p.max, edge_probability);
            else
                for (float& c : m.*p.color) c = draw(rng, p.min, p.max, edge_probability);
        }
        m.tangent_rotation = draw(rng, -2.0f * 3.14159265f, 2.0f * 3.14159265f, edge_probability);
        m.energy_compensation = rng.next_float() < 0.8f ? 1 : 0;
        return m;
    }
    brdf::Material m = brdf::default_material();
    for (const brdf::ScalarParameter& p : brdf::scalar_parameters()) {
        if (p.field) {
            m.*p.field = draw(rng, p.min, p.max, edge_probability) * p.to_material;
        } else {
            for (float& c : m.albedo) c = draw(rng, p.min, p.max, edge_probability);
        }
    }
    m.model = model;
    m.distribution = rng.next_float() < 0.5f ? BRDF_DISTRIBUTION_GGX : BRDF_DISTRIBUTION_HYPER_CAUCHY;
    return m;
}

brdf::Material random_material(UniformRandom& rng, int model) { return random_edge_material(rng, model, 0.0f); }

brdf::float3 uniform_sphere_direction(UniformRandom& rng) {
    double z = 1.0 - 2.0 * rng.next_double();
    double phi = 6.283185307179586 * rng.next_double();
    double r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
    return brdf::float3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

brdf::float3 uniform_hemisphere_direction(UniformRandom& rng) {
    brdf::float3 w = uniform_sphere_direction(rng);
    return brdf::float3(w.x, w.y, std::fabs(w.z));
}

}  // namespace lab::validation
