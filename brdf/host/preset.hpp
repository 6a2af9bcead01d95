// Material presets: JSON files (schema in docs/materials.md) loaded with validation.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "brdf/brdf.hpp"

namespace brdf {

struct Preset {
    std::string name;         // from the file, or the file's stem
    std::string description;
    std::string source;       // where it came from, for messages
    std::string measured;     // a measured preset's MERL file as the preset names it (relative to it)
    Material material;
};

// Throws lab::InputError naming the file and the field for an unreadable file, malformed JSON,
// an unknown key, a wrong type, a NaN or an out-of-range value.
Preset load_preset(const std::string& path);
// The same from the file's text; `source` names it in messages.
Preset parse_preset_text(const std::string& text, const std::string& source);
// `base_dir` resolves a relative "measured" path; empty: the folder of `source`.
Preset parse_preset(const nlohmann::json& document, const std::string& source, const std::string& base_dir = "");

// A parameter's value read from a file (JSON units): finite and within [lo, hi], where a value
// written with fewer digits than a bound may pass it by 1e-6 of the bound (clamped back into the
// range). Throws lab::InputError(source, field, ...) otherwise. Every reader of material files
// (presets, interchange/) checks its numbers with it.
float checked_parameter_value(double value, const std::string& source, const std::string& field, float lo, float hi);

// The shortest decimal that reads back as the same float (0.9f is written 0.9, not the double
// 0.8999999761581421 the float widens to), so saved presets and exported files read as typed.
double shortest_decimal(float value);

nlohmann::json preset_to_json(const Preset& preset);
void save_preset(const Preset& preset, const std::string& path);

}  // namespace brdf
