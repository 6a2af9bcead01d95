// The headless automation of `dtoadq view`: scripted parameter changes at given frames
// (`--set KEY=VALUE@FRAME`), and when the run ends (`--frames N`).
#pragma once

#include <string>
#include <vector>

#include "viewer/view_state.hpp"

namespace lab::viewer {

struct ScriptedSet {
    std::string key, value;
    int frame = 0;  // applied at the start of this frame (0: the first)
};

// "KEY=VALUE@FRAME"; "KEY=VALUE" means frame 0. Throws lab::InputError("--set", ...) when malformed.
ScriptedSet parse_scripted_set(const std::string& text);

// `--move KEY=VALUE@FRAME`: a camera or environment change as the mouse and the environment panel
// make it: orbit=DX,DY (a drag on the render, in pixels), env_rotation=DEGREES, env_exposure=STOPS,
// background_blur=DEGREES, background_opacity=A.
// Throws lab::InputError("--move", KEY, ...) for an unknown key or a bad value.
void apply_move(ViewState* state, const std::string& key, const std::string& value);

}  // namespace lab::viewer
