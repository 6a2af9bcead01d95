// The arithmetic of a rotate node, shared by the compiler (which writes it out as OpenCL C) and the
// host interpreter (which evaluates it), so both round alike: a component is the sum, left to right,
// of the matrix entries' non-zero products.
#pragma once

#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace lab::scene {

// Component `i` of R^T p (to the child's frame; inverse = true) or of R n (back to the world):
// (coefficient, component of the input) pairs, zero coefficients left out.
std::vector<std::pair<float, int>> rotation_terms(const glm::mat3& r, int i, bool inverse);

// Evaluates rotation_terms on the host.
Vec3 apply_rotation(const glm::mat3& r, Vec3 v, bool inverse);

}  // namespace lab::scene
