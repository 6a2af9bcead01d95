// Test materials: the parameter table's defaults with chosen lobe weights and a plain Lambert
// diffuse lobe (no retro-reflection, no subsurface), the starting point most tests tweak from.
#pragma once

#include "brdf/brdf.hpp"
#include "brdf/host/parameters.hpp"

inline brdf::Material lobe_material(float diffuse, float glossy, float specular, float transmission) {
    brdf::Material m = brdf::default_material();
    m.weight_diffuse = diffuse;
    m.weight_glossy = glossy;
    m.weight_specular = specular;
    m.weight_transmission = transmission;
    m.retroreflection = 0.0f;
    m.subsurface = 0.0f;
    return m;
}
