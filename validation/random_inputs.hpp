// Random materials and directions for the sweeps (reciprocity, robustness), drawn from the ranges
// of the parameter table so the sweeps follow it when it changes.
#pragma once

#include "brdf/brdf.hpp"
#include "validation/uniform_random.hpp"

namespace lab::validation {

// Every parameter of the table uniform in its range; distribution at random; the given model.
brdf::Material random_material(UniformRandom& rng, int model);

// As random_material, but each parameter is, with probability `edge_probability`, put at one end
// of its range (roughness 0 or 1, ior 1 or 3, all lobe weights 0, hc_shape at its bounds...).
brdf::Material random_edge_material(UniformRandom& rng, int model, float edge_probability);

brdf::float3 uniform_sphere_direction(UniformRandom& rng);
brdf::float3 uniform_hemisphere_direction(UniformRandom& rng);  // z >= 0

}  // namespace lab::validation
