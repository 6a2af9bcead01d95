// Writes an openpbr preset as pbrt-v4 scene text: a MakeNamedMaterial of pbrt's `diffuse`,
// `conductor`, `dielectric`, `coateddiffuse` or `coatedconductor` (the closest to the material's
// layers), a partial metal or transmission as a `mix` of named pure parts
// (interchange/base_mix.hpp). Roughness goes as GGX alphas (remaproughness false). Everything
// approximated or dropped is noted (docs/interchange.md).
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

std::string pbrt_text(const brdf::Preset& preset, Notes* notes);

}  // namespace interchange
