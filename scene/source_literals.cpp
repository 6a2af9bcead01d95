#include "scene/source_literals.hpp"

#include <cstdio>

namespace lab::scene {

std::string float_literal(float value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g", double(value));
    std::string s = text;
    if (s.find_first_of(".ein") == std::string::npos) {
        s += ".0";
    } else if (s.find('.') == std::string::npos && s.find('e') != std::string::npos) {
        s.insert(s.find('e'), ".0");
    }
    return s + "f";
}

std::string components_literal(Vec3 v) { return float_literal(v.x) + ", " + float_literal(v.y) + ", " + float_literal(v.z); }

std::string vec3_literal(Vec3 v) { return "make_float3(" + components_literal(v) + ")"; }

std::string component_names(const std::string& p) { return p + "x, " + p + "y, " + p + "z"; }

std::string offset_components(Vec3 c) {
    return "px - " + float_literal(c.x) + ", py - " + float_literal(c.y) + ", pz - " + float_literal(c.z);
}

}  // namespace lab::scene
