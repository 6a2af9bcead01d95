// The scene's extent as the renderer needs it beside the distance field: a sphere around what is
// bounded (CompiledScene::bounds_center, bounds_radius) and the box of every surface
// (surface_lo, surface_hi).
#pragma once

#include "scene/lipschitz.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

// The box of what is bounded: the camera, the lights, and each object's box about the origin
// (scene/lipschitz.hpp's extent) along its finite axes; then the sphere around that box. A scene
// with an endless part (a plane, an endless repetition) also holds the cube around the camera out to
// the distance of what it looks at: the environment's light subpaths start on a disk of this
// sphere's radius (kernels/bdpt_walk.h), so this is the part of an endless surface they cover;
// beyond it the camera's strategies carry the light alone (docs/bdpt.md).
void scene_bounds(const Scene& scene, Vec3* center, float* radius);

// The box of every surface (CompiledScene::surface_lo, surface_hi): the union of the objects'
// boxes, each holding its solid with f >= dist(p, box) outside it, and of the emitters' spheres.
// A plane with an axis for its normal bounds its axis on one side, the side of its solid, which
// the objects' centred boxes cannot say: the ground y = 0 is the box y <= 0, so that a ray
// going up from a scene on the ground stops marching above its objects. All of space when a
// repetition breaks the bound: then f >= dist(p, box) need not hold.
void surface_box(const Scene& scene, const SceneAnalysis& analysis, Vec3* lo, Vec3* hi);

}  // namespace lab::scene
