// The environment a scene file declares ("environment": a file or a constant, its rotation and
// exposure; docs/scenes.md), loaded: what `dtoadq render` lights a scene with when --env does not
// replace it, and what the tests render a scene under its own lights with.
#pragma once

#include <optional>
#include <string>

#include "ibl/environment.hpp"
#include "scene/scene.hpp"

namespace lab::render {

// The scene's environment with its rotation and exposure added to `options`' (the command line's
// on top of the file's); none when the scene declares none. *name, if given, gets the file or the
// "constant:R,G,B" spec it came from.
std::optional<ibl::Environment> load_scene_environment(const scene::Scene& scene, ibl::EnvironmentOptions options = {},
                                                       std::string* name = nullptr);

// What load_scene_environment loads, without loading it: the options it loads with, and in *source
// the file or the "constant:R,G,B" spec (the loaded environment's source()). The scene declares one.
ibl::EnvironmentOptions scene_environment_options(const scene::Scene& scene, ibl::EnvironmentOptions options, std::string* source);

}  // namespace lab::render
