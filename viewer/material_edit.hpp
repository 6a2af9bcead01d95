// Setting one material parameter by its preset key ("roughness", "lobes.glossy", "albedo", "model"),
// as `--set KEY=VALUE@FRAME` does. The edit goes through the preset's JSON form and its loader, so
// the ranges, spellings and messages are the preset file's own (brdf/host/preset, parameters).
#pragma once

#include <string>

#include "brdf/host/preset.hpp"

namespace lab::viewer {

// The preset with `key` set to `value`: a number; for albedo "r,g,b" or one number for all three
// (linear); for model and distribution their names; for energy_compensation true/false/1/0.
// Throws lab::InputError naming `origin` and the key for an unknown key or a bad value.
brdf::Preset with_parameter(const brdf::Preset& preset, const std::string& key, const std::string& value, const std::string& origin);

}  // namespace lab::viewer
