// "Export material": the edited material written for another tool (.mtlx, .gltf, .xml for Mitsuba 3,
// .pbrt) through interchange/, from the Presets panel and from `view --export-to FILE` on exit; a
// lab or measured material is fitted to openpbr first (docs/interchange.md).
#pragma once

#include <string>
#include <vector>

#include "brdf/host/preset.hpp"

namespace lab::viewer {

// Whether an --export-to target names a material file of another tool (by its extension) rather
// than SCENE.json:NAME.
bool is_material_file_target(const std::string& target);

// Writes the material; returns the notes, one line each ("FILE: FIELD: text"). Throws
// lab::InputError for an unknown extension, a material that cannot be fitted or a file that
// cannot be written.
std::vector<std::string> export_material_file(const brdf::Preset& preset, const std::string& path);

}  // namespace lab::viewer
