// A scene at a scene time t, in seconds (docs/scenes.md, "Time"): its camera and its environment's
// rotation follow their keyframes (scene/keyframes.hpp), and an emitter's image sequence or video
// shows frame floor(t * fps) (ibl/frame_source.hpp, read when the render's lights are built, at its
// scene time); nothing else in a scene moves or changes.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "scene/scene.hpp"

namespace lab::scene {

// The camera at time t: each keyframed field (position, look_at, up, fov_degrees and, for a thin
// lens, aperture_radius and focus_distance) at its interpolated value, the others as they are.
Camera camera_at(const Camera& camera, double t);

// What is wrong with a camera, as the key at fault and the problem, or nullopt: position and look_at
// equal, up zero or parallel to the view direction, a field of view outside (0, 180) degrees, a thin
// lens's aperture or focus distance not positive.
std::optional<std::pair<std::string, std::string>> camera_problem(const Camera& camera);

// The scene at time t: the camera and the environment's rotation at t. Throws lab::InputError
// naming the scene file and the keyframes when the camera at t is not a camera (a Catmull-Rom
// spline can overshoot between keyframes that are each fine).
Scene scene_at_time(const Scene& scene, double t);

// Whether anything in the scene changes with time: keyframes, or an emitter that plays an image
// sequence or a video.
bool is_animated(const Scene& scene);

}  // namespace lab::scene
