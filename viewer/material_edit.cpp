#include "viewer/material_edit.hpp"

#include <cstdlib>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdf/host/parameters.hpp"
#include "common/input_error.hpp"

namespace lab::viewer {

namespace {

double parse_number(const std::string& text, const std::string& origin, const std::string& key) {
    const char* begin = text.c_str();
    char* end = nullptr;
    double v = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size()) throw InputError(origin, key, "expected a number, got \"" + text + "\"");
    return v;  // NaN and infinities pass here; the preset loader refuses them by name
}

// albedo, or one of OpenPBR's colour inputs (base_color, coat_color, ...)
bool is_color_key(const std::string& key) {
    if (key == "albedo") return true;
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters())
        if (!p.field && key == p.key) return true;
    return false;
}

}  // namespace

brdf::Preset with_parameter(const brdf::Preset& preset, const std::string& key, const std::string& value, const std::string& origin) {
    nlohmann::json doc = brdf::preset_to_json(preset);
    if (key == "model" || key == "distribution") {
        doc[key] = value;
    } else if (key == "energy_compensation") {
        if (value != "true" && value != "false" && value != "1" && value != "0")
            throw InputError(origin, key, "expected true, false, 1 or 0, got \"" + value + "\"");
        doc[key] = value == "true" || value == "1";
    } else if (is_color_key(key)) {
        std::vector<double> rgb;
        std::stringstream parts(value);
        for (std::string part; std::getline(parts, part, ',');) rgb.push_back(parse_number(part, origin, key));
        if (rgb.size() == 1) rgb.assign(3, rgb[0]);
        if (rgb.size() != 3) throw InputError(origin, key, "expected one number or three (r,g,b), got \"" + value + "\"");
        doc[key] = rgb;
    } else if (key.rfind("lobes.", 0) == 0) {
        doc["lobes"][key.substr(6)] = parse_number(value, origin, key);
    } else {
        doc[key] = parse_number(value, origin, key);
    }
    // The loader checks the key exists, the type and the range, and names the field.
    brdf::Preset out = brdf::parse_preset(doc, origin);
    out.source = preset.source;
    return out;
}

}  // namespace lab::viewer
