// The headless automation of `dtoadq view`: scripted parameter changes at given frames
// (`--set KEY=VALUE@FRAME`), and when the run ends (`--frames N`).
#pragma once

#include <string>
#include <vector>

namespace lab::viewer {

struct ScriptedSet {
    std::string key, value;
    int frame = 0;  // applied at the start of this frame (0: the first)
};

// "KEY=VALUE@FRAME"; "KEY=VALUE" means frame 0. Throws lab::InputError("--set", ...) when malformed.
ScriptedSet parse_scripted_set(const std::string& text);

}  // namespace lab::viewer
