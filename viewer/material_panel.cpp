#include "viewer/material_panel.hpp"

#include <cstring>
#include <string>

#include <imgui.h>

#include "brdf/host/parameters.hpp"
#include "film/tone_map.hpp"

namespace lab::viewer {

namespace {

// One scalar: slider and numeric entry in JSON units (degrees for angles), reset to the preset.
bool scalar_row(const brdf::ScalarParameter& p, brdf::Material* m, const brdf::Material& preset) {
    bool changed = false;
    float value = m->*p.field / p.to_material;
    ImGui::PushID(p.key);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
    // a range over several decades (emission_luminance, nits) is a logarithmic slider, so that 1 and 1000 are both reachable
    const bool decades = p.min >= 0.0f && p.max > 1000.0f;
    changed |= ImGui::SliderFloat("##slider", &value, p.min, p.max, decades ? "%.4g" : "%.3f",
                                  ImGuiSliderFlags_AlwaysClamp | (decades ? ImGuiSliderFlags_Logarithmic : 0));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70.0f);
    if (ImGui::InputFloat("##entry", &value, 0.0f, 0.0f, "%.4f", ImGuiInputTextFlags_EnterReturnsTrue)) changed = true;
    ImGui::SameLine();
    const bool at_preset = m->*p.field == preset.*p.field;
    if (at_preset) ImGui::BeginDisabled();
    if (ImGui::SmallButton("reset")) {
        m->*p.field = preset.*p.field;
        ImGui::PopID();
        if (at_preset) ImGui::EndDisabled();
        return true;
    }
    if (at_preset) ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextUnformatted(p.key);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s%s%s", p.meaning, *p.unit ? "\nunit: " : "", p.unit);
    ImGui::PopID();
    if (changed) {
        // A typed value is clamped to the table's range, as the preset loader would refuse it.
        if (!(value >= p.min)) value = p.min;
        if (value > p.max) value = p.max;
        m->*p.field = value * p.to_material;
    }
    return changed;
}

// A colour: picker in sRGB, stored linear, reset to the preset.
bool color_row(const char* key, float (brdf::Material::*field)[3], brdf::Material* m, const brdf::Material& preset) {
    float* linear = m->*field;
    float srgb[3];
    for (int c = 0; c < 3; ++c) srgb[c] = film::srgb_encode(linear[c]);
    ImGui::PushID(key);
    std::string label = std::string(key) + " (sRGB)";
    bool changed = ImGui::ColorEdit3(label.c_str(), srgb, ImGuiColorEditFlags_Float);
    if (changed)
        for (int c = 0; c < 3; ++c) linear[c] = film::srgb_decode(srgb[c] < 0.0f ? 0.0f : (srgb[c] > 1.0f ? 1.0f : srgb[c]));
    ImGui::SameLine();
    if (ImGui::SmallButton("reset")) {
        std::memcpy(linear, preset.*field, sizeof(float) * 3);
        changed = true;
    }
    ImGui::Text("linear %.4f %.4f %.4f", linear[0], linear[1], linear[2]);
    ImGui::PopID();
    return changed;
}

bool albedo_row(brdf::Material* m, const brdf::Material& preset) { return color_row("albedo", &brdf::Material::albedo, m, preset); }

// OpenPBR's inputs in OpenPBR's groups (base, specular, transmission, subsurface, coat, fuzz, thin film).
bool openpbr_panel(brdf::Material* m, const brdf::Material& preset) {
    bool changed = false;
    ImGui::TextUnformatted("model: openpbr (OpenPBR Surface 1.1)");
    bool compensation = m->energy_compensation != 0;
    if (ImGui::Checkbox("energy compensation", &compensation)) {
        m->energy_compensation = compensation ? 1 : 0;
        changed = true;
    }
    std::string group;
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        if (group != p.group) {
            group = p.group;
            ImGui::Separator();
            ImGui::TextUnformatted(p.group);
        }
        changed |= p.field ? scalar_row(p, m, preset) : color_row(p.key, p.color, m, preset);
    }
    return changed;
}

}  // namespace

bool material_panel(brdf::Material* m, const brdf::Material& preset) {
    bool changed = false;
    if (m->model == BRDF_MODEL_MEASURED) {  // its table is the BRDF: no parameter applies
        ImGui::TextUnformatted("measured (MERL table): no parameters to edit");
        return false;
    }
    if (m->model == BRDF_MODEL_OPENPBR) return openpbr_panel(m, preset);
    int model = m->model == BRDF_MODEL_DTOADQ2017 ? 1 : 0;
    if (ImGui::Combo("model", &model, "lab\0dtoadq2017\0")) {
        m->model = model == 1 ? BRDF_MODEL_DTOADQ2017 : BRDF_MODEL_LAB;
        changed = true;
    }
    int distribution = m->distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY ? 1 : 0;
    if (ImGui::Combo("distribution", &distribution, "ggx\0hyper_cauchy\0")) {
        m->distribution = distribution == 1 ? BRDF_DISTRIBUTION_HYPER_CAUCHY : BRDF_DISTRIBUTION_GGX;
        changed = true;
    }
    bool compensation = m->energy_compensation != 0;
    if (ImGui::Checkbox("energy compensation", &compensation)) {
        m->energy_compensation = compensation ? 1 : 0;
        changed = true;
    }
    changed |= albedo_row(m, preset);
    for (const brdf::ScalarParameter& p : brdf::scalar_parameters()) {
        if (!p.field) continue;  // the albedo has its colour picker
        if (std::strcmp(p.key, "lobes.diffuse") == 0) {
            ImGui::Separator();
            ImGui::TextUnformatted("lobe weights");
        }
        changed |= scalar_row(p, m, preset);
    }
    return changed;
}

}  // namespace lab::viewer
