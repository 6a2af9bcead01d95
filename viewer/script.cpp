#include "viewer/script.hpp"

#include <cstdlib>

#include "common/input_error.hpp"
#include "viewer/camera_controller.hpp"

namespace lab::viewer {

ScriptedSet parse_scripted_set(const std::string& text) {
    ScriptedSet s;
    size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", "", "expected KEY=VALUE@FRAME, got \"" + text + "\"");
    s.key = text.substr(0, eq);
    std::string rest = text.substr(eq + 1);
    size_t at = rest.rfind('@');
    if (at != std::string::npos) {
        std::string frame = rest.substr(at + 1);
        char* end = nullptr;
        long f = std::strtol(frame.c_str(), &end, 10);
        if (frame.empty() || *end != '\0' || f < 0 || f > 10000000)
            throw InputError("--set", s.key, "expected a frame number in [0, 10000000] after @, got \"" + frame + "\"");
        s.frame = int(f);
        rest = rest.substr(0, at);
    }
    if (rest.empty()) throw InputError("--set", s.key, "no value");
    s.value = rest;
    return s;
}

namespace {

// A finite number in [lo, hi], the whole text.
float number(const std::string& key, const std::string& text, float lo, float hi) {
    char* end = nullptr;
    const float v = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
        throw InputError("--move", key, "expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got \"" + text + "\"");
    return v;
}

}  // namespace

void apply_move(ViewState* state, const std::string& key, const std::string& value) {
    if (key == "orbit") {
        const size_t comma = value.find(',');
        if (comma == std::string::npos) throw InputError("--move", key, "expected DX,DY in pixels, got \"" + value + "\"");
        orbit(&state->camera, number(key, value.substr(0, comma), -1e4f, 1e4f), number(key, value.substr(comma + 1), -1e4f, 1e4f));
    } else if (key == "env_rotation") {
        state->env_rotation_degrees = number(key, value, -360.0f, 360.0f);
    } else if (key == "env_exposure") {
        state->env_exposure_stops = number(key, value, -64.0f, 64.0f);
    } else if (key == "background_blur") {
        state->background_blur_degrees = number(key, value, 0.0f, 90.0f);
    } else if (key == "background_opacity") {
        state->background_opacity = number(key, value, 0.0f, 1.0f);
    } else {
        throw InputError("--move", key, "unknown key (orbit, env_rotation, env_exposure, background_blur, background_opacity)");
    }
}

}  // namespace lab::viewer
