#include "scene/scene_time.hpp"

#include <algorithm>
#include <cstdio>

#include "common/input_error.hpp"
#include "ibl/frame_source.hpp"
#include "scene/json_fields.hpp"

namespace lab::scene {

namespace {

Vec3 vec3_of(const std::vector<double>& v) { return Vec3(float(v[0]), float(v[1]), float(v[2])); }

std::string seconds_text(double t) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", t);
    return text;
}

}  // namespace

Camera camera_at(const Camera& camera, double t) {
    Camera c = camera;
    if (!camera.keyframes) return c;
    const Keyframes& k = *camera.keyframes;
    for (const Track& track : k.tracks) {
        const std::vector<double> v = track_value(k, track, t);
        if (track.name == "position") c.position = vec3_of(v);
        else if (track.name == "look_at") c.look_at = vec3_of(v);
        else if (track.name == "up") c.up = vec3_of(v);
        else if (track.name == "fov_degrees") c.fov_degrees = float(v[0]);
        else if (track.name == "aperture_radius") c.aperture_radius = float(v[0]);
        else if (track.name == "focus_distance") c.focus_distance = float(v[0]);
    }
    return c;
}

std::optional<std::pair<std::string, std::string>> camera_problem(const Camera& c) {
    if (c.look_at == c.position) return std::make_pair(std::string("look_at"), std::string("equals camera.position: there is no view direction"));
    if (c.up == Vec3(0.0f)) return std::make_pair(std::string("up"), std::string("must not be the zero vector"));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(c.look_at) - glm::dvec3(c.position));
    if (glm::length(glm::cross(forward, glm::normalize(glm::dvec3(c.up)))) < 1e-6)
        return std::make_pair(std::string("up"), std::string("is parallel to the view direction (look_at - position)"));
    if (!(c.fov_degrees > 0.0f && c.fov_degrees < 180.0f))
        return std::make_pair(std::string("fov_degrees"), "value " + format_number(c.fov_degrees) + " is out of range (0, 180)");
    if (c.type == CameraType::thin_lens && !(c.aperture_radius > 0.0f))
        return std::make_pair(std::string("aperture_radius"), "value " + format_number(c.aperture_radius) + " must be > 0");
    if (c.type == CameraType::thin_lens && !(c.focus_distance > 0.0f))
        return std::make_pair(std::string("focus_distance"), "value " + format_number(c.focus_distance) + " must be > 0");
    return std::nullopt;
}

Scene scene_at_time(const Scene& scene, double t) {
    Scene s = scene;
    if (scene.camera.keyframes) {
        s.camera = camera_at(scene.camera, t);
        if (auto problem = camera_problem(s.camera))
            throw InputError(scene.file, scene.camera.keyframes->path,
                             "at t = " + seconds_text(t) + " s the camera's " + problem->first + " " + problem->second);
    }
    if (scene.environment && scene.environment->keyframes) {
        const Keyframes& k = *scene.environment->keyframes;
        s.environment->rotation_degrees = float(track_value(k, *k.find("rotation_degrees"), t)[0]);
    }
    return s;
}

bool is_animated(const Scene& scene) {
    const bool playing = std::any_of(scene.emitters.begin(), scene.emitters.end(), [](const Emitter& e) {
        return !e.image.empty() && (e.image_fps || ibl::is_video_path(e.image));  // a sequence or a video
    });
    return playing || scene.camera.keyframes || (scene.environment && scene.environment->keyframes);
}

}  // namespace lab::scene
