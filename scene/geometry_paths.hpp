// Which objects are intersected exactly and which are sphere-traced (docs/scenes.md, "Geometry
// paths"): an object that is one plain primitive under rigid transforms and uniform scales, with no
// blend, domain operator or displacement, has a closed-form hit (sdf/exact/); the rest, the
// primitives inside a blend or a combination included, are fields to march. Emitters are intersected
// exactly. `--geometry march` (Scene::march_everything) marches everything that has a volume: every
// object and the emissive spheres; rect and disk emitters stay exact.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace lab::scene {

bool object_is_exact(const Scene& scene, const Object& object);
bool emitter_is_exact(const Scene& scene, const Emitter& emitter);

// The objects and emitters the march's field holds.
int marched_count(const Scene& scene);

// One line per object, then per emitter: its name, path and which way it goes, and why.
std::vector<std::string> geometry_paths(const Scene& scene);

}  // namespace lab::scene
