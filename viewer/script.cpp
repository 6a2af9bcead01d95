#include "viewer/script.hpp"

#include <cstdlib>

#include "common/input_error.hpp"

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

}  // namespace lab::viewer
