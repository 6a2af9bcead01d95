#include "viewer/view_menu.hpp"

#include <cmath>
#include <cstdio>

#include <imgui.h>

namespace lab::viewer {

namespace {

ImVec4 colour(const std::array<uint8_t, 3>& rgb) { return ImVec4(float(rgb[0]) / 255.0f, float(rgb[1]) / 255.0f, float(rgb[2]) / 255.0f, 1.0f); }

// One swatch a band, labelled with its stops from middle grey, in two rows (the panel's narrowest
// column holds six).
void legend() {
    ImGui::TextUnformatted("stops from 18% grey (each band up to the next):");
    const std::vector<LegendBand>& bands = false_colour_legend();
    for (size_t i = 0; i < bands.size(); ++i) {
        const LegendBand& band = bands[i];
        if (i == (bands.size() + 1) / 2) ImGui::NewLine();
        char label[32];
        if (std::isinf(band.lo_stops)) std::snprintf(label, sizeof label, "<%+.0f", band.hi_stops);
        else if (std::isinf(band.hi_stops)) std::snprintf(label, sizeof label, ">=%+.0f", band.lo_stops);
        else std::snprintf(label, sizeof label, "%+.0f", band.lo_stops);
        ImGui::ColorButton(label, colour(band.rgb), ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(14, 14));
        ImGui::SameLine(0.0f, 2.0f);
        ImGui::TextUnformatted(label);
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

}  // namespace

bool save_exr_controls(char* path, size_t path_size, char* layers, size_t layers_size) {
    ImGui::SetNextItemWidth(150.0f);
    ImGui::InputText("##exr path", path, path_size);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(170.0f);
    ImGui::InputText("##exr layers", layers, layers_size);
    ImGui::SameLine();
    return ImGui::Button("save EXR");
}

bool view_menu(ViewMode* mode, float* relative_error_threshold) {
    bool changed = false;
    ImGui::SetNextItemWidth(150.0f);
    if (ImGui::BeginCombo("view", view_mode_name(*mode).c_str())) {
        for (const auto& [m, name] : view_modes())
            if (ImGui::Selectable(name.c_str(), m == *mode) && m != *mode) {
                *mode = m;
                changed = true;
            }
        ImGui::EndCombo();
    }
    switch (*mode) {
    case ViewMode::false_colour: legend(); break;
    case ViewMode::relative_error:
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120.0f);
        changed |= ImGui::SliderFloat("threshold", relative_error_threshold, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
        ImGui::TextUnformatted("red: standard error / mean above it (wait longer there)");
        break;
    case ViewMode::gamut: ImGui::TextUnformatted("magenta: NaN/inf   cyan: negative   red: above 1 after exposure"); break;
    case ViewMode::variance: ImGui::TextUnformatted("the mean's standard error (sqrt scale to the 99th percentile); magenta: < 2 samples"); break;
    case ViewMode::samples: ImGui::TextUnformatted("finite samples per pixel over the largest count"); break;
    case ViewMode::depth: ImGui::TextUnformatted("nearest / depth: the nearest white, twice as far half; no surface black"); break;
    case ViewMode::normal: ImGui::TextUnformatted("world-space normal as (n + 1) / 2"); break;
    default: break;
    }
    return changed;
}

}  // namespace lab::viewer
