// Reads a MaterialX document's material as an openpbr preset: the first <surfacematerial> (or the
// one named), its
// surfaceshader an `open_pbr_surface` (inputs by name, OpenPBR Surface 1.1) or a `standard_surface`
// (translated as MaterialX's translation graph does, interchange/standard_surface.hpp). What it
// cannot carry (textures and other connections, node graphs, further materials, inputs the lab
// leaves out set away from their defaults) becomes one note each; malformed input (not XML, not
// MaterialX, no material, an unknown node or input, a wrong type, a value out of the lab's range, a
// file too large) throws lab::InputError naming the file and the element. docs/interchange.md.
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

// `material` names the <surfacematerial> to read; empty: the first (the others are noted).
Imported read_mtlx(const std::string& path, const std::string& material = "");
// The same from the document's text; `source` names it in messages.
Imported parse_mtlx_text(const std::string& text, const std::string& source, const std::string& material = "");

}  // namespace interchange
