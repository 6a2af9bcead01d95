// Pieces of the OpenCL C the scene compiler writes: floats and vectors as literals, and a point as
// the three components the distance functions take.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace lab::scene {

// A float as an OpenCL C literal that reads back as exactly the same float: "%.9g", a decimal
// point, and the f suffix ("1.0f", "-0.25f", "1.5e-07f").
std::string float_literal(float value);

// "x, y, z": a vector as the three arguments of a component form (sdf/, fX_xyz).
std::string components_literal(Vec3 v);

// "make_float3(x, y, z)".
std::string vec3_literal(Vec3 v);

// The distance functions take the point as three SDF_FLOATs ("px, py, pz" for the point named "p"),
// one point or, under SDF_LANES, a packet of eight (docs/sdf.md, "Component forms and packets").
// Normals keep float3.
std::string component_names(const std::string& p);

// The components of p - c: "px - cx, py - cy, pz - cz".
std::string offset_components(Vec3 c);

}  // namespace lab::scene
