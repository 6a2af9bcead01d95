// Writes an openpbr preset as a MaterialX 1.39 document: one `open_pbr_surface` node holding every
// OpenPBR input the lab evaluates, and a `surfacematerial` naming it. OpenPBR's inputs are the lab's
// own, so every value is carried as is; what OpenPBR has no input for (the lab's
// energy_compensation off) is noted. docs/interchange.md.
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

std::string mtlx_text(const brdf::Preset& preset, Notes* notes);

}  // namespace interchange
