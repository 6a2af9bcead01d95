// The text of a compiled scene's two virtual headers: scene/generated.h (the distance field, its
// nearest-object search, material slots and analytic normals) and scene/materials.h (the feature
// switches of its materials).
#pragma once

#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "scene/lipschitz.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

// scene/generated.h: every object's functions, then the field in both forms (the packet kernels'
// scene_distance_xyz under SDF_LANES, else scene_nearest and what is built on it); object_bounds
// switches the box tests on.
std::string generate_source(const Scene& scene, const SceneAnalysis& analysis, bool object_bounds);

// scene/materials.h: apart from the geometry, so that a kernel that only marches (the packet
// kernels, the scene probe) is the same program for every material and is compiled once.
std::string generate_material_source(const Scene& scene, const std::vector<brdf::Material>& materials);

}  // namespace lab::scene
