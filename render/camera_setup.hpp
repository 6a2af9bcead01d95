// The kernel's camera (kernels/camera.h) from a scene's camera and the image size.
#pragma once

#include <string>

#include "kernels/host.hpp"
#include "scene/scene.hpp"

namespace lab::render {

// Pinhole or thin lens (docs/scenes.md). Throws lab::InputError naming `file` and the field
// (camera.aperture_radius, camera.focus_distance, camera.fov_degrees) for parameters the camera
// cannot use: a thin lens with a non-positive or non-finite aperture or focus distance, a field of
// view outside (0, 180); std::invalid_argument for a size below 1 x 1.
kernel::Camera make_camera(const scene::Camera& camera, int width, int height, const std::string& file);

}  // namespace lab::render
