// Reads a glTF 2.0 document's first material (or the one named) as an openpbr preset: pbrMetallicRoughness and the
// KHR_materials_* extensions the writer uses (interchange/gltf_writer.hpp), by the mapping of
// docs/interchange.md. Textures, other extensions, further materials and alpha modes are noted one
// line each; malformed input (not JSON, not glTF 2.0, no material, a wrong type, a value out of the
// lab's range, a file too large) throws lab::InputError naming the file and the element.
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

// `material` names the material to read, by its name or its index in `materials`; empty: the first
// (the others are noted).
Imported read_gltf(const std::string& path, const std::string& material = "");
// The same from the document's text; `source` names it in messages.
Imported parse_gltf_text(const std::string& text, const std::string& source, const std::string& material = "");

}  // namespace interchange
