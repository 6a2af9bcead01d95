// The object grids of the per-object figures (`bench objects`, `bench compare`): N objects on a
// square grid under a constant sky, and the least-squares slope that turns their cost per path into
// the cost of one more object.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace lab::cli {

// `count` objects on a square grid (spacing 1.2), cycling through a costly blend (a turned rounded
// box smoothly joined to a torus), a sphere and a capsule; a camera above that sees them all; a
// constant sky. No floor: rays grazing a plane take hundreds of steps whatever the objects, which
// would hide what the objects cost. As a scene file's JSON, so that another build can render it.
nlohmann::json grid_scene_json(int count);

scene::Scene grid_scene(int count);

// Least-squares slope of y against x (0 when all x are equal).
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace lab::cli
