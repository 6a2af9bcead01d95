// Writes an openpbr preset as a glTF 2.0 document holding one material: pbrMetallicRoughness and
// the KHR_materials_* extensions that carry OpenPBR's layers (clearcoat, sheen, iridescence,
// specular, ior, transmission, anisotropy, emissive_strength), each written only where it differs
// from glTF's default, and listed in extensionsUsed. Every parameter glTF cannot express, or
// expresses with another formula, is noted. docs/interchange.md gives the table.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

nlohmann::json gltf_document(const brdf::Preset& preset, Notes* notes);
std::string gltf_text(const brdf::Preset& preset, Notes* notes);

}  // namespace interchange
