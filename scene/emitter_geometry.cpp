#include "scene/emitter_geometry.hpp"

#include <cmath>

namespace lab::scene {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Vec3 rect_dual_u(const Emitter& e) { return glm::cross(e.edge_v, e.normal) / glm::length(glm::cross(e.edge_u, e.edge_v)); }

Vec3 rect_dual_v(const Emitter& e) { return glm::cross(e.normal, e.edge_u) / glm::length(glm::cross(e.edge_u, e.edge_v)); }

double emitter_area(const Emitter& e) {
    switch (e.shape) {
    case EmitterShape::rect: return double(glm::length(glm::cross(e.edge_u, e.edge_v)));
    case EmitterShape::disk: return kPi * double(e.radius) * double(e.radius);
    case EmitterShape::sphere: break;
    }
    return 4.0 * kPi * double(e.radius) * double(e.radius);
}

}  // namespace lab::scene
