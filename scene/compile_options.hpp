// The options a scene is compiled with: materials replaced and objects left out by name, the
// object bounds switched on or off, and everything marched or the plain primitives intersected.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

// What a viewer changes without editing the file.
struct CompileOptions {
    std::map<std::string, brdf::Material> material_overrides;  // declared material name -> its replacement
    std::vector<std::string> disabled_objects;                 // object names to leave out
    // Skip, at each point, an object whose bounding box is no nearer than the nearest surface found
    // so far (the field is unchanged; docs/scenes.md, "Object bounds"), and end a ray's march once
    // it has left the box of every surface (the same hits). Off for comparisons.
    bool object_bounds = true;
    // Sphere-trace every object, the plain primitives too (scene/geometry_paths.hpp): the images of
    // a field-only renderer, to compare. Off: plain primitives and emitters are intersected exactly.
    bool march_everything = false;
};

// The scene with the options applied. Throws lab::InputError naming the scene file for a name the
// scene does not declare, or when nothing would be left to render.
Scene apply_options(const Scene& scene, const CompileOptions& options);

}  // namespace lab::scene
