// Orbit, pan and zoom of the scene camera about its look-at point, from mouse movement in pixels.
#pragma once

#include "scene/scene.hpp"

namespace lab::viewer {

// Turns the camera about the look-at point: dx about the up axis, dy towards or away from it
// (kept short of the poles). 0.4 degrees per pixel.
void orbit(scene::Camera* camera, float dx_pixels, float dy_pixels);
// Moves the camera and its look-at point together across the view, by the view's width at the
// look-at distance per `image_width` pixels.
void pan(scene::Camera* camera, float dx_pixels, float dy_pixels, int image_width);
// Scales the distance to the look-at point by 0.9 per step (positive: closer).
void zoom(scene::Camera* camera, float steps);

}  // namespace lab::viewer
