#include "brdf/host/preset.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "brdf/host/measured_registry.hpp"
#include "brdf/host/parameters.hpp"
#include "common/input_error.hpp"
#include "common/read_text_file.hpp"

namespace brdf {
namespace {

// Far beyond any real preset (a few hundred bytes, two levels of objects): refused with a line of
// their own instead of filling memory.
constexpr std::uintmax_t kMaxPresetFileBytes = 1u << 20;
constexpr int kMaxPresetNesting = 32;

using nlohmann::json;
using lab::InputError;
using lab::read_text_file;

const json* find_key(const json& doc, const std::string& key) {
    auto dot = key.find('.');
    if (dot == std::string::npos) return doc.contains(key) ? &doc.at(key) : nullptr;
    std::string group = key.substr(0, dot);
    if (!doc.contains(group) || !doc.at(group).is_object()) return nullptr;
    const json& inner = doc.at(group);
    std::string rest = key.substr(dot + 1);
    return inner.contains(rest) ? &inner.at(rest) : nullptr;
}

float checked_number(const json& value, const std::string& source, const std::string& key, float lo, float hi) {
    if (!value.is_number())
        throw InputError(source, key, std::string("expected a number, got ") + value.type_name());
    return checked_parameter_value(value.get<double>(), source, key, lo, hi);
}

int parse_enum(const json& doc, const std::string& source, const std::string& key, const char* a, int va, const char* b, int vb,
               int fallback) {
    if (!doc.contains(key)) return fallback;
    const json& value = doc.at(key);
    if (!value.is_string()) throw InputError(source, key, std::string("expected a string, got ") + value.type_name());
    std::string s = value.get<std::string>();
    if (s == a) return va;
    if (s == b) return vb;
    throw InputError(source, key, "unknown value \"" + s + "\" (expected \"" + a + "\" or \"" + b + "\")");
}

// The model a preset names: lab (the default), dtoadq2017 or openpbr.
int parse_model(const json& doc, const std::string& source) {
    if (!doc.contains("model")) return BRDF_MODEL_LAB;
    const json& value = doc.at("model");
    if (!value.is_string()) throw InputError(source, "model", std::string("expected a string, got ") + value.type_name());
    const std::string s = value.get<std::string>();
    for (int model : {BRDF_MODEL_LAB, BRDF_MODEL_DTOADQ2017, BRDF_MODEL_OPENPBR})
        if (s == model_name(model)) return model;
    throw InputError(source, "model", "unknown value \"" + s + "\" (expected \"lab\", \"dtoadq2017\" or \"openpbr\")");
}

// An openpbr preset: OpenPBR's input names as flat keys, each left out at OpenPBR's default.
void reject_unknown_openpbr_keys(const json& doc, const std::string& source) {
    std::set<std::string> top = {"name", "description", "model", "energy_compensation"};
    for (const ScalarParameter& p : openpbr_parameters()) top.insert(p.key);
    for (auto it = doc.begin(); it != doc.end(); ++it)
        if (!top.count(it.key())) throw InputError(source, it.key(), "unknown key for model \"openpbr\" (its keys are OpenPBR Surface's inputs)");
}

void reject_unknown_keys(const json& doc, const std::string& source) {
    std::set<std::string> top = {"name", "description", "model", "distribution", "energy_compensation", "lobes", "measured"};
    std::set<std::string> lobes;
    for (const ScalarParameter& p : scalar_parameters()) {
        std::string key = p.key;
        if (key.rfind("lobes.", 0) == 0)
            lobes.insert(key.substr(6));
        else
            top.insert(key);
    }
    for (auto it = doc.begin(); it != doc.end(); ++it)
        if (!top.count(it.key())) throw InputError(source, it.key(), "unknown key");
    if (doc.contains("lobes")) {
        const json& l = doc.at("lobes");
        if (!l.is_object()) throw InputError(source, "lobes", std::string("expected an object, got ") + l.type_name());
        for (auto it = l.begin(); it != l.end(); ++it)
            if (!lobes.count(it.key())) throw InputError(source, "lobes." + it.key(), "unknown key");
    }
}

// "measured": a MERL file, relative to the preset's folder. Its problems (missing, truncated, bad
// entries) are reported as the preset's field, with the MERL reader's line after it.
void parse_measured(const json& doc, const std::string& source, const std::string& base_dir, Preset* preset) {
    const json& value = doc.at("measured");
    if (!value.is_string()) throw InputError(source, "measured", std::string("expected a file path (string), got ") + value.type_name());
    if (doc.contains("model")) throw InputError(source, "model", "a measured preset has no model (its table is the BRDF)");
    std::string relative = value.get<std::string>();
    std::filesystem::path file(relative);
    if (file.is_relative()) file = std::filesystem::path(base_dir) / file;
    std::error_code ec;
    if (relative.empty() || !std::filesystem::is_regular_file(file, ec))
        throw InputError(source, "measured", "MERL file \"" + relative + "\" not found (looked for " + file.string() + ")");
    try {
        preset->material.measured_offset = register_measured_file(file.string());
    } catch (const InputError& e) {
        throw InputError(source, "measured", e.what());
    }
    preset->material.model = BRDF_MODEL_MEASURED;
    preset->measured = relative;
}


// A colour: an array of 3 numbers, each within the entry's range.
void parse_color(const json& value, const std::string& source, const ScalarParameter& p, float* rgb) {
    if (!value.is_array() || value.size() != 3) throw InputError(source, p.key, "expected an array of 3 numbers (linear RGB)");
    for (int c = 0; c < 3; ++c) rgb[c] = checked_number(value.at(c), source, std::string(p.key) + "[" + std::to_string(c) + "]", p.min, p.max);
}

}  // namespace

float checked_parameter_value(double v, const std::string& source, const std::string& field, float lo, float hi) {
    if (!std::isfinite(v)) throw InputError(source, field, "not a finite number");
    // a little slack for values written with fewer digits than the bounds, relative to each bound
    // (one of the upper bound's would let -1 nit below 0 with an upper bound of 1e6 nits)
    auto slack = [](float bound) { return 1e-6 * std::max(1.0, std::fabs(double(bound))); };
    if (v < lo - slack(lo) || v > hi + slack(hi)) {
        std::ostringstream msg;
        msg << "value " << v << " is out of range [" << lo << ", " << hi << "]";
        throw InputError(source, field, msg.str());
    }
    return float(std::min(std::max(v, double(lo)), double(hi)));
}

Preset parse_preset(const json& doc, const std::string& source, const std::string& base_dir) {
    if (!doc.is_object()) throw InputError(source, "", "a preset must be a JSON object");
    const int model = doc.contains("measured") ? BRDF_MODEL_LAB : parse_model(doc, source);
    if (model == BRDF_MODEL_OPENPBR)
        reject_unknown_openpbr_keys(doc, source);
    else
        reject_unknown_keys(doc, source);
    Preset preset;
    preset.source = source;
    preset.material = default_material(model);
    preset.name = std::filesystem::path(source).stem().string();
    for (const char* key : {"name", "description"}) {
        if (!doc.contains(key)) continue;
        if (!doc.at(key).is_string()) throw InputError(source, key, std::string("expected a string, got ") + doc.at(key).type_name());
        (std::string(key) == "name" ? preset.name : preset.description) = doc.at(key).get<std::string>();
    }
    if (model == BRDF_MODEL_OPENPBR) {
        if (doc.contains("energy_compensation")) {
            const json& value = doc.at("energy_compensation");
            if (!value.is_boolean())
                throw InputError(source, "energy_compensation", std::string("expected true or false, got ") + value.type_name());
            preset.material.energy_compensation = value.get<bool>() ? 1 : 0;
        }
        for (const ScalarParameter& p : openpbr_parameters()) {
            if (!doc.contains(p.key)) continue;
            if (p.field)
                preset.material.*p.field = checked_number(doc.at(p.key), source, p.key, p.min, p.max);
            else
                parse_color(doc.at(p.key), source, p, preset.material.*p.color);
        }
        return preset;
    }
    preset.material.model = model;
    preset.material.distribution = parse_enum(doc, source, "distribution", "ggx", BRDF_DISTRIBUTION_GGX, "hyper_cauchy",
                                              BRDF_DISTRIBUTION_HYPER_CAUCHY, BRDF_DISTRIBUTION_GGX);
    if (doc.contains("energy_compensation")) {
        const json& value = doc.at("energy_compensation");
        if (!value.is_boolean())
            throw InputError(source, "energy_compensation", std::string("expected true or false, got ") + value.type_name());
        preset.material.energy_compensation = value.get<bool>() ? 1 : 0;
    }
    if (doc.contains("measured"))
        parse_measured(doc, source, base_dir.empty() ? std::filesystem::path(source).parent_path().string() : base_dir, &preset);
    for (const ScalarParameter& p : scalar_parameters()) {
        const json* value = find_key(doc, p.key);
        if (!value) continue;
        if (p.field) {
            preset.material.*p.field = checked_number(*value, source, p.key, p.min, p.max) * p.to_material;
            continue;
        }
        parse_color(*value, source, p, preset.material.albedo);  // the albedo
    }
    return preset;
}

Preset load_preset(const std::string& path) { return parse_preset_text(read_text_file(path, kMaxPresetFileBytes, "preset"), path); }

Preset parse_preset_text(const std::string& text, const std::string& path) {
    json doc;
    std::string last_key;  // the field being read when parsing fails
    try {
        doc = json::parse(text, [&last_key, &path](int depth, json::parse_event_t event, json& value) {
            if (event == json::parse_event_t::key) last_key = value.get<std::string>();
            // a preset is two levels deep (the lobes object); nothing legitimate comes near this
            if (depth > kMaxPresetNesting)
                throw InputError(path, last_key, "nested more than " + std::to_string(kMaxPresetNesting) + " levels deep");
            return true;
        });
    } catch (const json::exception& e) {  // syntax errors, and number overflow such as 1e999
        // nlohmann's message names the byte offset; keep its text after the "[json.exception...]" tag
        std::string what = e.what();
        auto pos = what.find("] ");
        throw InputError(path, last_key, "malformed JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
    }
    return parse_preset(doc, path);
}

double shortest_decimal(float value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    if (error != std::errc()) return double(value);
    return std::strtod(std::string(text, end).c_str(), nullptr);
}

json preset_to_json(const Preset& preset) {
    json doc;
    doc["name"] = preset.name;
    if (!preset.description.empty()) doc["description"] = preset.description;
    if (preset.material.model == BRDF_MODEL_OPENPBR) {
        doc["model"] = model_name(BRDF_MODEL_OPENPBR);
        doc["energy_compensation"] = preset.material.energy_compensation != 0;
        for (const ScalarParameter& p : openpbr_parameters()) {
            if (p.field) {
                doc[p.key] = shortest_decimal(preset.material.*p.field);
                continue;
            }
            const float* rgb = preset.material.*p.color;
            doc[p.key] = {shortest_decimal(rgb[0]), shortest_decimal(rgb[1]), shortest_decimal(rgb[2])};
        }
        return doc;
    }
    if (preset.material.model == BRDF_MODEL_MEASURED)
        doc["measured"] = preset.measured;
    else
        doc["model"] = model_name(preset.material.model);
    doc["distribution"] = distribution_name(preset.material.distribution);
    doc["energy_compensation"] = preset.material.energy_compensation != 0;
    for (const ScalarParameter& p : scalar_parameters()) {
        json value;
        if (p.field)
            value = shortest_decimal(preset.material.*p.field / p.to_material);
        else
            value = {shortest_decimal(preset.material.albedo[0]), shortest_decimal(preset.material.albedo[1]),
                     shortest_decimal(preset.material.albedo[2])};
        std::string key = p.key;
        if (key.rfind("lobes.", 0) == 0)
            doc["lobes"][key.substr(6)] = value;
        else
            doc[key] = value;
    }
    return doc;
}

void save_preset(const Preset& preset, const std::string& path) {
    std::ofstream out(path);
    if (!out) throw lab::InputError(path, "", "cannot write preset file");
    out << preset_to_json(preset).dump(2) << "\n";
}

}  // namespace brdf
