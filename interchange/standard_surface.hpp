// Autodesk Standard Surface's inputs and their translation to OpenPBR Surface, as MaterialX's own
// translation graph does it (libraries/bxdf/translation/standard_surface_to_open_pbr.mtlx in
// MaterialX 1.39): the lab imports a `standard_surface` node by this mapping (docs/interchange.md).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

// An input of a shader node: its MaterialX type and default.
struct NodeInput {
    const char* name;
    const char* type;  // "float", "color3", "boolean", "vector3"
    std::array<float, 3> fallback;
};

// Standard Surface's inputs with the defaults of its nodedef (ND_standard_surface_surfaceshader).
const std::vector<NodeInput>& standard_surface_inputs();

// Standard Surface input values (every input, defaults filled in) to OpenPBR input values, by the
// translation graph's rules; inputs it does not translate (specular_rotation, coat_affect_color,
// transmission_extra_roughness, ...) are noted when they differ from their defaults, under
// `element`/NAME.
std::map<std::string, std::array<float, 3>> standard_surface_to_openpbr(const std::map<std::string, std::array<float, 3>>& standard,
                                                                         const std::string& element, Notes* notes);

}  // namespace interchange
