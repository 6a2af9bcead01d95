// "Export to scene": the material written into a scene file under a name, adding it or replacing
// the material of that name, and leaving every other key of the file as it was (same values, same
// order; the file is re-indented by two spaces, as the bundled scenes are). The new file is checked
// by the scene loader before it replaces the old one, atomically.
#pragma once

#include <string>

#include "brdf/host/preset.hpp"

namespace lab::viewer {

// "SCENE.json:NAME" split at the last colon; throws lab::InputError("--export-to", ...) when either
// part is empty.
void parse_export_target(const std::string& text, std::string* scene_file, std::string* material_name);

// Throws lab::InputError naming the scene file (unreadable, malformed, not an object, `materials`
// not an object, or the result refused by the scene loader); the file is then untouched.
void export_to_scene(const brdf::Preset& preset, const std::string& scene_file, const std::string& material_name);

}  // namespace lab::viewer
