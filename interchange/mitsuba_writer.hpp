// Writes an openpbr preset as a Mitsuba 3 scene fragment: one <bsdf> (id: the preset's name) of
// Mitsuba's documented plugins. A coat or fuzz takes `principled` (its clearcoat and sheen); a
// partial metal or transmission a `blendbsdf` of pure parts (interchange/base_mix.hpp); a metal
// `principled` with metallic 1 (Schlick's Fresnel of the base colour, as the lab's F82 with a white
// tint); glass `dielectric` or `roughdielectric`; an opaque dielectric `plastic` or `roughplastic`,
// or `diffuse` without a specular. Everything approximated or dropped is noted (docs/interchange.md).
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

std::string mitsuba_text(const brdf::Preset& preset, Notes* notes);

}  // namespace interchange
