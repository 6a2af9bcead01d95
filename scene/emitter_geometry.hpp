// What the compiler, the host interpreter and the light set derive from a rect or disk emitter's
// fields (scene/scene.hpp): the dual vectors that give a rect point's coordinates and each shape's
// area.
#pragma once

#include "scene/scene.hpp"

namespace lab::scene {

// For a rect: du = (V x n) / |U x V|, dv = (n x U) / |U x V|, so that a point q of its plane (from
// its centre) is x U + y V with x = du.q, y = dv.q.
Vec3 rect_dual_u(const Emitter& e);
Vec3 rect_dual_v(const Emitter& e);

// |U x V| for a rect, pi r^2 for a disk, 4 pi r^2 for a sphere.
double emitter_area(const Emitter& e);

}  // namespace lab::scene
