#include "interchange/openpbr_mapping.hpp"

#include <charconv>

#include "common/input_error.hpp"

namespace interchange {

std::string note_line(const std::string& file, const Note& note) {
    return file + ": " + note.field + (note.field.empty() ? "" : ": ") + note.text;
}

void Notes::add(const std::string& field, const std::string& text) {
    for (const Note& n : items)
        if (n.field == field && n.text == text) return;
    items.push_back({field, text});
}

bool Notes::names(const std::string& field) const {
    for (const Note& n : items)
        if (n.field == field) return true;
    return false;
}

const brdf::ScalarParameter* lab_openpbr_parameter(const std::string& name) {
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters())
        if (name == p.key) return &p;
    return nullptr;
}

const std::vector<LeftOutInput>& openpbr_inputs_left_out() {
    static const char* const kMedia = "the lab renders no participating medium";
    static const std::vector<LeftOutInput> table{
        {"transmission_depth", "float", {0, 0, 0}, kMedia, "transmission_weight"},
        {"transmission_scatter", "color3", {0, 0, 0}, kMedia, "transmission_weight"},
        {"transmission_scatter_anisotropy", "float", {0, 0, 0}, kMedia, "transmission_weight"},
        {"transmission_dispersion_scale", "float", {0, 0, 0}, "the lab renders no dispersion", "transmission_weight"},
        {"transmission_dispersion_abbe_number", "float", {20, 0, 0}, "the lab renders no dispersion", "transmission_weight"},
        {"subsurface_radius", "float", {1, 0, 0}, "the lab's subsurface lobe is single scattering at the surface, without a mean free path", "subsurface_weight"},
        {"subsurface_radius_scale", "color3", {1.0f, 0.5f, 0.25f}, "the lab's subsurface lobe is single scattering at the surface, without a mean free path", "subsurface_weight"},
        {"geometry_opacity", "float", {1, 0, 0}, "the lab's surfaces are opaque to the camera", nullptr},
        {"geometry_thin_walled", "boolean", {0, 0, 0}, "the lab's surfaces bound solids (not thin-walled)", nullptr},
        {"geometry_normal", "vector3", {0, 0, 0}, "the lab shades with the geometric normal", nullptr},
        {"geometry_coat_normal", "vector3", {0, 0, 0}, "the lab shades with the geometric normal", nullptr},
        {"geometry_tangent", "vector3", {0, 0, 0}, "the lab's tangent comes from the surface", nullptr},
        {"geometry_coat_tangent", "vector3", {0, 0, 0}, "the lab's tangent comes from the surface", nullptr},
    };
    return table;
}

std::array<float, 3> parameter_value(const brdf::Material& m, const brdf::ScalarParameter& p) {
    if (p.field) return {m.*p.field, 0.0f, 0.0f};
    const float* rgb = m.*p.color;
    return {rgb[0], rgb[1], rgb[2]};
}

void set_parameter_value(brdf::Material* m, const brdf::ScalarParameter& p, const std::array<float, 3>& value) {
    if (p.field) {
        m->*p.field = value[0];
        return;
    }
    for (int c = 0; c < 3; ++c) (m->*p.color)[c] = value[c];
}

std::vector<std::string> silent_changes(const brdf::Material& written, const brdf::Material& read, const Notes& notes,
                                        const std::vector<std::string>& skip) {
    std::vector<std::string> out;
    auto text = [](const std::array<float, 3>& v, int n) {
        std::string t;
        for (int c = 0; c < n; ++c) t += (c ? " " : "") + float_text(v[c]);
        return t;
    };
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        bool skipped = false;
        for (const std::string& s : skip) skipped = skipped || s == p.key;
        if (skipped || notes.names(p.key)) continue;
        const std::array<float, 3> a = parameter_value(written, p), b = parameter_value(read, p);
        if (a != b) out.push_back(std::string(p.key) + ": " + text(a, parameter_components(p)) + " -> " + text(b, parameter_components(p)));
    }
    if (written.energy_compensation != read.energy_compensation && !notes.names("energy_compensation")) out.push_back("energy_compensation");
    return out;
}

std::string float_text(float value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    if (error != std::errc()) return std::to_string(value);
    return std::string(text, end);
}

void require_openpbr(const brdf::Preset& preset) {
    if (preset.material.model == BRDF_MODEL_OPENPBR) return;
    throw lab::InputError(preset.source, "model",
                          std::string("a \"") + brdf::model_name(preset.material.model) +
                              "\" material has no OpenPBR inputs: the writers take openpbr materials (convert fits the others first, docs/interchange.md)");
}

std::string identifier(const std::string& name) {
    std::string out;
    for (char c : name) {
        const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        const bool digit = c >= '0' && c <= '9';
        out += (letter || digit) ? c : '_';
    }
    if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out = "M_" + out;
    return out;
}

}  // namespace interchange
