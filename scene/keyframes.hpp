// Keyframes: values of a scene that change with the scene time (docs/scenes.md, "Time"), given at
// a list of times and interpolated between them, linearly or by a Catmull-Rom spline. The camera
// and the environment's rotation hold them (scene/scene_time.hpp evaluates a scene at a time).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lab::scene {

enum class Interpolation {
    linear,
    // A cubic Hermite spline through every keyframe whose tangent at keyframe i is
    // (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]) (uniform Catmull-Rom when the times are evenly spaced)
    // and, at the first and last keyframes, the one-sided difference to their neighbour.
    catmull_rom,
};

// One keyframed quantity: `components` numbers per keyframe (3 for a point, 1 for an angle).
struct Track {
    std::string name;           // its key in the keyframes object: "position", "fov_degrees"
    int components = 1;
    std::vector<float> values;  // keyframe-major: keyframe k's component c is values[k * components + c]
};

struct Keyframes {
    std::string path;  // where they are in the scene file ("camera.keyframes"), for messages
    Interpolation interpolation = Interpolation::linear;
    std::vector<float> times;  // seconds, strictly increasing
    std::vector<Track> tracks;

    const Track* find(const std::string& name) const;
};

// Before the first keyframe a value holds the first one's, after the last the last one's; at a
// keyframe's time it is that keyframe's exactly.
double interpolate(const std::vector<float>& times, const Track& track, int component, Interpolation interpolation, double t);

// The track's value at time t: its `components` numbers.
std::vector<double> track_value(const Keyframes& keyframes, const Track& track, double t);

// What a track may hold: its key, how many numbers per keyframe, and the range of each number
// ([lo, hi], or (lo, hi) when `open`).
struct TrackSpec {
    std::string name;
    int components = 1;
    float lo, hi;
    bool open = false;
};

// Reads {"interpolation": "linear" | "catmull_rom" (default linear), "times": [...], and one array
// per track, one entry per time} at `path`. Throws lab::InputError naming the file and the field:
// an unknown key, no track, times that do not increase strictly, a track whose length is not the
// times', a value out of its range, fewer keyframes than the interpolation needs (2 linear, 3
// Catmull-Rom).
Keyframes parse_keyframes(const nlohmann::ordered_json& value, const std::string& path, const std::string& file, const std::vector<TrackSpec>& specs);

}  // namespace lab::scene
