#include "viewer/panels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

#include "render/camera_setup.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/material_export.hpp"
#include "viewer/pixel_probe.hpp"
#include "viewer/material_export.hpp"
#include "viewer/scene_export.hpp"

namespace lab::viewer {

void environment_panel(UiState* ui, bool* changed, bool* retone, std::string* load_env, scene::LookDevReferences* references,
                       bool* references_changed) {
    // The maps in envmaps/ (from the working folder), or any path typed in.
    std::error_code ec;
    std::vector<std::string> maps;
    for (const auto& entry : std::filesystem::directory_iterator("envmaps", ec)) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".exr" || ext == ".hdr") maps.push_back(entry.path().generic_string());
    }
    std::sort(maps.begin(), maps.end());
    for (const std::string& m : maps) {
        if (ImGui::SmallButton(std::filesystem::path(m).stem().string().c_str())) *load_env = m;
        ImGui::SameLine();
    }
    ImGui::NewLine();
    ImGui::InputText("##envpath", ui->env_path, sizeof ui->env_path);
    ImGui::SameLine();
    if (ImGui::Button("load map")) *load_env = ui->env_path;
    *changed |= ImGui::SliderFloat("rotation", &ui->view.env_rotation_degrees, -180.0f, 180.0f, "%.1f deg");
    *changed |= ImGui::SliderFloat("light (stops)", &ui->view.env_exposure_stops, -8.0f, 8.0f, "%.2f");
    *changed |= ImGui::Checkbox("background", &ui->view.show_background);
    // the backdrop only: lighting, mirrors and glass keep the map as it is (kernels/background.h);
    // a blur is applied when the slider is let go, since each angle prefilters the map anew
    ImGui::SliderFloat("background blur", &ui->view.background_blur_degrees, 0.0f, 30.0f, "%.1f deg");
    *changed |= ImGui::IsItemDeactivatedAfterEdit();
    *changed |= ImGui::SliderFloat("background opacity", &ui->view.background_opacity, 0.0f, 1.0f, "%.2f");
    int tone = int(ui->tone_map);
    if (ImGui::Combo("tone map", &tone, "aces\0reinhard\0clamp\0")) {
        ui->tone_map = film::ToneMap(tone);
        *retone = true;
    }
    *retone |= ImGui::SliderFloat("display exposure", &ui->display_exposure, -8.0f, 8.0f, "%.2f");
    ImGui::TextUnformatted("references:");
    ImGui::SameLine();
    *references_changed |= ImGui::Checkbox("chrome ball", &references->chrome_ball);
    ImGui::SameLine();
    *references_changed |= ImGui::Checkbox("grey ball", &references->grey_ball);
    ImGui::SameLine();
    *references_changed |= ImGui::Checkbox("chart", &references->color_chart);
    // the ground as a shadow catcher: the backdrop with the model's shadows (docs/environments.md)
    *references_changed |= ImGui::Checkbox("shadow catcher", &references->shadow_catcher);
}

bool preset_panel(UiState* ui) {
    bool loaded = false;
    ImGui::InputText("preset file", ui->preset_path, sizeof ui->preset_path);
    if (ImGui::Button("load preset")) {
        try {
            ui->reference = brdf::load_preset(ui->preset_path);  // a bad file throws: nothing changes
            ui->preset = ui->reference;
            ui->message = std::string("loaded ") + ui->preset_path;
            loaded = true;
        } catch (const std::exception& e) {
            ui->message = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("save preset")) {
        try {
            brdf::save_preset(ui->preset, ui->preset_path);
            ui->message = std::string("saved ") + ui->preset_path;
        } catch (const std::exception& e) {
            ui->message = e.what();
        }
    }
    ImGui::InputText("scene:name", ui->export_target, sizeof ui->export_target);
    if (ImGui::Button("export to scene")) {
        try {
            std::string file, name;
            parse_export_target(ui->export_target, &file, &name);
            export_to_scene(ui->preset, file, name);
            ui->message = "exported " + name + " into " + file;
        } catch (const std::exception& e) {
            ui->message = e.what();  // the scene file is untouched
        }
    }
    ImGui::InputText("file (.mtlx .gltf .xml .pbrt)", ui->export_file, sizeof ui->export_file);
    if (ImGui::Button("export material")) {
        try {
            const std::vector<std::string> notes = export_material_file(ui->preset, ui->export_file);
            ui->message = std::string("exported ") + ui->export_file + (notes.empty() ? "" : ": " + std::to_string(notes.size()) + " note(s) on stderr");
            for (const std::string& n : notes) std::fprintf(stderr, "dtoadq: note: %s\n", n.c_str());
        } catch (const std::exception& e) {
            ui->message = e.what();
        }
    }
    return loaded;
}

// Mouse over the render: orbit, pan, zoom, turn the environment, pick a pixel to inspect.
// Returns whether the view changed.
bool mouse_on_render(UiState* ui, const Rect& image, int render_width, int render_height, int* picked_x, int* picked_y) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || !image.contains(io.MousePos.x, io.MousePos.y)) return false;
    bool changed = false;
    const ImVec2 d = io.MouseDelta;
    const float divider = image.x + ui->split_x * image.w;
    static bool moving_divider = false;  // one mouse, one window
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) moving_divider = ui->split && std::fabs(io.MousePos.x - divider) < 6.0f;
    if (moving_divider && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        ui->split_x = std::clamp((io.MousePos.x - image.x) / image.w, 0.0f, 1.0f);
        return false;  // both renders go on: nothing to restart
    }
    // Drags pan by screen pixels of the image as drawn, whatever the render's own size.
    const int drawn_width = std::max(1, int(image.w));
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (d.x != 0.0f || d.y != 0.0f)) {
        if (io.KeyCtrl)
            ui->view.env_rotation_degrees = std::fmod(ui->view.env_rotation_degrees + d.x * 0.5f + 540.0f, 360.0f) - 180.0f;
        else if (io.KeyShift)
            pan(&ui->view.camera, d.x, d.y, drawn_width);
        else
            orbit(&ui->view.camera, d.x, d.y);
        changed = true;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f) && (d.x != 0.0f || d.y != 0.0f)) {
        pan(&ui->view.camera, d.x, d.y, drawn_width);
        changed = true;
    }
    if (io.MouseWheel != 0.0f) {
        zoom(&ui->view.camera, io.MouseWheel);
        changed = true;
    }
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        *picked_x = std::min(render_width - 1, int((io.MousePos.x - image.x) * float(render_width) / image.w));
        *picked_y = std::min(render_height - 1, int((io.MousePos.y - image.y) * float(render_height) / image.h));
    }
    return changed;
}

// The inspector's lines for pixel (x, y): film radiance and samples, then the probe's geometry.
std::vector<std::string> inspect_pixel(const ViewerConfig& config, const scene::Scene& scene, const UiState& ui, const RenderFrame& frame,
                                       const RenderWorker& worker, int x, int y) {
    std::vector<std::string> lines;
    char line[256];
    std::snprintf(line, sizeof line, "pixel %d,%d", x, y);
    lines.push_back(line);
    if (frame.image.valid() && x >= 0 && y >= 0 && x < frame.image.width && y < frame.image.height) {
        std::array<float, 3> L = frame.image.at(x, y);
        std::snprintf(line, sizeof line, "radiance %.4g %.4g %.4g (%d samples)", L[0], L[1], L[2], frame.samples_per_pixel);
        lines.push_back(line);
    }
    kernel::RenderKernelSettings launch_settings;
    if (!worker.kernel_settings(&launch_settings)) return lines;
    try {
        const int width = ui.view.width > 0 ? ui.view.width : config.width, height = ui.view.height > 0 ? ui.view.height : config.height;
        kernel::Camera camera = render::make_camera(ui.view.camera, width, height, scene.file);
        PixelProbe p = probe_pixel(scene, launch_settings, camera, x, y);
        if (!p.hit) {
            lines.push_back("no surface: the environment");
            return lines;
        }
        std::snprintf(line, sizeof line, "depth %.4f", p.depth);
        lines.push_back(line);
        std::snprintf(line, sizeof line, "normal %.3f %.3f %.3f", p.normal.x, p.normal.y, p.normal.z);
        lines.push_back(line);
        const bool named = p.material >= 0 && size_t(p.material) < scene.materials.size();
        std::snprintf(line, sizeof line, "material slot %d (%s)", p.material, named ? scene.materials[size_t(p.material)].name.c_str() : "?");
        lines.push_back(line);
    } catch (const std::exception& e) {
        lines.push_back(e.what());
    }
    return lines;
}

void inspector_panel(const ViewerConfig& config, const scene::Scene& scene, const UiState& ui, const RenderFrame& frame, const RenderWorker& worker,
                     int x, int y) {
    if (x < 0) {
        ImGui::TextUnformatted("right-click a pixel of the render");
        return;
    }
    for (const std::string& line : inspect_pixel(config, scene, ui, frame, worker, x, y)) ImGui::TextUnformatted(line.c_str());
}

void help_panel() {
    ImGui::TextUnformatted("Esc: quit    R: restart accumulation    B: background on/off");
    ImGui::TextUnformatted("On the render: drag to orbit, Shift+drag or middle-drag to pan,");
    ImGui::TextUnformatted("wheel to zoom, Ctrl+drag to turn the environment,");
    ImGui::TextUnformatted("right-click to inspect a pixel (Inspector)");
    ImGui::TextUnformatted("A/B split (View): drag the divider; B is --compare");
    ImGui::TextUnformatted("Lobe panel: drag on the polar plot for theta in, on the 3D view to turn it");
    ImGui::TextUnformatted("Sliders: drag, or Ctrl+click to type; the entry box takes Enter");
    ImGui::TextUnformatted("reset: back to the preset's value");
    ImGui::TextUnformatted("Every change restarts the accumulation.");
}

}  // namespace lab::viewer
