// Reading a scene file (docs/scenes.md, schema docs/scene.schema.json) into a validated Scene.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace lab::scene {

// Every bad input throws lab::InputError "FILE: FIELD: problem", FIELD the JSON path of the field
// ("objects[2].shape.children[0].radius"). Preset files named by the scene are read here (relative
// paths against the scene file's folder); their own errors name the preset file.
Scene load_scene(const std::string& path);

// The same from text; `file` names the scene in messages and anchors its relative paths.
Scene parse_scene(const std::string& text, const std::string& file);

}  // namespace lab::scene
