// The shape nodes of a scene file: `{"type": "...", ...}` objects (docs/scenes.md, "Nodes").
#pragma once

#include <string>
#include <vector>

#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

// Every node type a scene file may name, in documentation order.
const std::vector<std::string>& node_type_names();

// Parses and validates one node and its subtree; errors name `file` and the field's JSON path.
Node parse_node(const Json& value, const std::string& path, const std::string& file);

}  // namespace lab::scene
