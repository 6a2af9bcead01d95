// The scene's distance field evaluated on the host with the same sdf/ headers the compiled source
// uses (sdf/sdf.hpp), operation for operation: for tests (the compiled scene on an OpenCL device
// must agree) and host-side tools. Takes the scene as compile_scene() sees it: apply_options()
// first where options are used.
#pragma once

#include "scene/scene.hpp"

namespace lab::scene {

// One node's field at p (in the node's parent frame).
float shape_distance(const Node& node, Vec3 p);

// The generated scene_distance / scene_distance_material / scene_analytic_normal.
float scene_distance(const Scene& scene, Vec3 p);
float scene_distance_material(const Scene& scene, Vec3 p, int* material);
int scene_analytic_normal(const Scene& scene, Vec3 p, Vec3* n);

// The generated scene_march_distance (the field without what is intersected exactly, INFINITY when
// that is everything), scene_exact_hit (the nearest exact hit with t in (0, t_max], INFINITY for
// none) and scene_surface (the nearest object's material slot and, when it is intersected exactly,
// 1 and its analytic normal, else 0); scene/geometry_paths.hpp says which objects are.
float scene_march_distance(const Scene& scene, Vec3 p);
float scene_exact_hit(const Scene& scene, Vec3 o, Vec3 v, float t_max);
int scene_surface(const Scene& scene, Vec3 p, int* slot, Vec3* n);

}  // namespace lab::scene
