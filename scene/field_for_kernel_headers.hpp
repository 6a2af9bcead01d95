// The scene's distance field as the free functions the single-source kernel headers call
// (scene_distance, scene_distance_material, scene_analytic_normal, and the split between exact
// hits and the march: scene_march_distance, scene_exact_hit, scene_surface,
// scene_march_objects; in a kernel the generated
// scene/generated.h defines them), for the host builds of those headers: the host renderer and the
// viewer's pixel probe. They evaluate, through the host interpreter, the scene this thread set in
// `current_scene`. A host build brings them in with
// `using namespace lab::scene::field_for_kernel_headers;` in the namespace that includes
// sdf/march.h and the kernel headers.
#pragma once

#include "scene/geometry_paths.hpp"
#include "scene/interpreter.hpp"

namespace lab::scene::field_for_kernel_headers {

inline thread_local const Scene* current_scene = nullptr;

inline float scene_distance(Vec3 p) { return scene::scene_distance(*current_scene, p); }
inline float scene_distance_material(Vec3 p, int* material) { return scene::scene_distance_material(*current_scene, p, material); }
inline int scene_analytic_normal(Vec3 p, Vec3* n) { return scene::scene_analytic_normal(*current_scene, p, n); }
inline float scene_march_distance(Vec3 p) { return scene::scene_march_distance(*current_scene, p); }
inline float scene_exact_hit(Vec3 o, Vec3 v, float t_max) { return scene::scene_exact_hit(*current_scene, o, v, t_max); }
inline int scene_surface(Vec3 p, int* slot, Vec3* n) { return scene::scene_surface(*current_scene, p, slot, n); }
inline int scene_march_objects() { return scene::marched_count(*current_scene); }

}  // namespace lab::scene::field_for_kernel_headers
