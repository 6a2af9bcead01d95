#include "viewer/camera_controller.hpp"

#include <algorithm>
#include <cmath>

#include "common/angles.hpp"

namespace lab::viewer {

void orbit(scene::Camera* c, float dx, float dy) {
    const scene::Vec3 up = glm::normalize(c->up);
    scene::Vec3 offset = c->position - c->look_at;
    const float distance = glm::length(offset);
    if (!(distance > 0.0f)) return;
    // Yaw about up (Rodrigues' rotation), then pitch about the view's right axis.
    auto rotate = [](scene::Vec3 v, scene::Vec3 axis, float angle) {
        return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) + axis * glm::dot(axis, v) * (1.0f - std::cos(angle));
    };
    offset = rotate(offset, up, -dx * 0.4f * kRadiansPerDegree);
    const float elevation = std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
    const float pitch = std::clamp(elevation + dy * 0.4f * kRadiansPerDegree, -85.0f * kRadiansPerDegree, 85.0f * kRadiansPerDegree) - elevation;
    const scene::Vec3 right = glm::normalize(glm::cross(up, offset));
    offset = rotate(offset, right, -pitch);
    c->position = c->look_at + offset;
}

void pan(scene::Camera* c, float dx, float dy, int image_width) {
    const scene::Vec3 forward = c->look_at - c->position;
    const float distance = glm::length(forward);
    if (!(distance > 0.0f) || image_width < 1) return;
    const scene::Vec3 right = glm::normalize(glm::cross(forward, c->up));
    const scene::Vec3 up = glm::normalize(glm::cross(right, forward));
    const float per_pixel = 2.0f * distance * std::tan(0.5f * c->fov_degrees * kRadiansPerDegree) / float(image_width);
    const scene::Vec3 move = (-right * dx + up * dy) * per_pixel;
    c->position += move;
    c->look_at += move;
}

void zoom(scene::Camera* c, float steps) {
    const scene::Vec3 offset = c->position - c->look_at;
    const float scale = std::pow(0.9f, steps);
    if (glm::length(offset) * scale > 1e-3f) c->position = c->look_at + offset * scale;
}

}  // namespace lab::viewer
