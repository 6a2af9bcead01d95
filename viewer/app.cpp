#include "viewer/app.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "common/input_error.hpp"
#include "render/camera_setup.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/gl_image.hpp"
#include "viewer/lobe_panel.hpp"
#include "viewer/material_edit.hpp"
#include "viewer/material_panel.hpp"
#include "viewer/pixel_probe.hpp"
#include "viewer/scene_export.hpp"
#include "viewer/validation_badges.hpp"

namespace lab::viewer {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

constexpr int kPanelWidth = 400;
constexpr int kMinWindowHeight = 560;
// Headless runs give up waiting for the image to show their last change after this long.
constexpr double kScriptTimeoutSeconds = 120.0;

// GLFW's own errors, kept for the one line the viewer fails with.
std::string g_glfw_error;
void on_glfw_error(int code, const char* text) { g_glfw_error = std::to_string(code) + " " + (text ? text : ""); }

struct GlfwSession {
    GlfwSession() {
        glfwSetErrorCallback(on_glfw_error);
        if (!glfwInit())
            throw std::runtime_error("cannot open a window (no display? under ssh or CI run it through xvfb-run): GLFW " + g_glfw_error);
    }
    ~GlfwSession() { glfwTerminate(); }
};

// Everything the interface edits, and what it last handed to the render worker.
struct UiState {
    ViewState view;
    brdf::Preset preset;  // the edited material (preset.material mirrors view.materials[slot])
    film::ToneMap tone_map = film::ToneMap::Aces;
    float display_exposure = 0.0f;
    char preset_path[512] = "material.json";
    char export_target[512] = "scene.json:material";
    std::string message;  // the last error or confirmation, shown in the panel
};

void environment_panel(UiState* ui, bool* changed, bool* retone) {
    *changed |= ImGui::SliderFloat("rotation", &ui->view.env_rotation_degrees, -180.0f, 180.0f, "%.1f deg");
    *changed |= ImGui::SliderFloat("light (stops)", &ui->view.env_exposure_stops, -8.0f, 8.0f, "%.2f");
    *changed |= ImGui::Checkbox("background", &ui->view.show_background);
    int tone = int(ui->tone_map);
    if (ImGui::Combo("tone map", &tone, "aces\0reinhard\0clamp\0")) {
        ui->tone_map = film::ToneMap(tone);
        *retone = true;
    }
    *retone |= ImGui::SliderFloat("display exposure", &ui->display_exposure, -8.0f, 8.0f, "%.2f");
}

void preset_panel(UiState* ui) {
    ImGui::InputText("preset file", ui->preset_path, sizeof ui->preset_path);
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
}

// Mouse over the render: orbit, pan, zoom, turn the environment, pick a pixel to inspect.
// Returns whether the view changed.
bool mouse_on_render(UiState* ui, int width, int height, int* picked_x, int* picked_y) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || io.MousePos.x < 0 || io.MousePos.x >= float(width) || io.MousePos.y < 0 || io.MousePos.y >= float(height))
        return false;
    bool changed = false;
    const ImVec2 d = io.MouseDelta;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (d.x != 0.0f || d.y != 0.0f)) {
        if (io.KeyCtrl)
            ui->view.env_rotation_degrees = std::fmod(ui->view.env_rotation_degrees + d.x * 0.5f + 540.0f, 360.0f) - 180.0f;
        else if (io.KeyShift)
            pan(&ui->view.camera, d.x, d.y, width);
        else
            orbit(&ui->view.camera, d.x, d.y);
        changed = true;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f) && (d.x != 0.0f || d.y != 0.0f)) {
        pan(&ui->view.camera, d.x, d.y, width);
        changed = true;
    }
    if (io.MouseWheel != 0.0f) {
        zoom(&ui->view.camera, io.MouseWheel);
        changed = true;
    }
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        *picked_x = int(io.MousePos.x);
        *picked_y = int(io.MousePos.y);
    }
    return changed;
}

// The inspector's lines for pixel (x, y): film radiance and samples, then the probe's geometry.
std::vector<std::string> inspect_pixel(const ViewerConfig& config, const UiState& ui, const RenderFrame& frame, const RenderWorker& worker, int x,
                                       int y) {
    std::vector<std::string> lines;
    char line[256];
    std::snprintf(line, sizeof line, "pixel %d,%d", x, y);
    lines.push_back(line);
    if (frame.image.valid() && x >= 0 && y >= 0 && x < frame.image.width && y < frame.image.height) {
        std::array<float, 3> L = frame.image.at(x, y);
        std::snprintf(line, sizeof line, "radiance %.4g %.4g %.4g (%d samples)", L[0], L[1], L[2], frame.samples_per_pixel);
        lines.push_back(line);
    }
    kernel::RenderKernelSettings k;
    if (!worker.kernel_settings(&k)) return lines;
    try {
        kernel::Camera camera = render::make_camera(ui.view.camera, config.width, config.height, config.scene.file);
        PixelProbe p = probe_pixel(config.scene, k, camera, x, y);
        if (!p.hit) {
            lines.push_back("no surface: the environment");
            return lines;
        }
        std::snprintf(line, sizeof line, "depth %.4f", p.depth);
        lines.push_back(line);
        std::snprintf(line, sizeof line, "normal %.3f %.3f %.3f", p.normal.x, p.normal.y, p.normal.z);
        lines.push_back(line);
        const bool named = p.material >= 0 && size_t(p.material) < config.scene.materials.size();
        std::snprintf(line, sizeof line, "material slot %d (%s)", p.material, named ? config.scene.materials[size_t(p.material)].name.c_str() : "?");
        lines.push_back(line);
    } catch (const std::exception& e) {
        lines.push_back(e.what());
    }
    return lines;
}

void inspector_panel(const ViewerConfig& config, const UiState& ui, const RenderFrame& frame, const RenderWorker& worker, int x, int y) {
    if (x < 0) {
        ImGui::TextUnformatted("right-click a pixel of the render");
        return;
    }
    for (const std::string& line : inspect_pixel(config, ui, frame, worker, x, y)) ImGui::TextUnformatted(line.c_str());
}

void help_panel() {
    ImGui::TextUnformatted("Esc: quit    R: restart accumulation    B: background on/off");
    ImGui::TextUnformatted("On the render: drag to orbit, Shift+drag or middle-drag to pan,");
    ImGui::TextUnformatted("wheel to zoom, Ctrl+drag to turn the environment,");
    ImGui::TextUnformatted("right-click to inspect a pixel (Inspector)");
    ImGui::TextUnformatted("Lobe panel: drag on the polar plot for theta in, on the 3D view to turn it");
    ImGui::TextUnformatted("Sliders: drag, or Ctrl+click to type; the entry box takes Enter");
    ImGui::TextUnformatted("reset: back to the preset's value");
    ImGui::TextUnformatted("Every change restarts the accumulation.");
}

}  // namespace

int run_viewer(const ViewerConfig& config) {
    GlfwSession glfw;
    const bool headless = config.frames > 0;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    const int window_width = config.width + kPanelWidth;
    const int window_height = config.height > kMinWindowHeight ? config.height : kMinWindowHeight;
    if (headless) glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(window_width, window_height, config.title.c_str(), nullptr, nullptr);
    if (!window) throw std::runtime_error("cannot open a window (no OpenGL 3.0 context?): GLFW " + g_glfw_error);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(headless ? 0 : 1);  // headless frames are not paced by a display

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 130");

    UiState ui;
    ui.view = config.initial;
    ui.preset = config.preset;
    ui.preset.material = ui.view.materials.at(size_t(config.edited_slot));
    ui.tone_map = config.tone_map;
    ui.display_exposure = config.display_exposure;

    int exit_status = 0;
    FrameStats stats;
    LobePanel lobes;
    ValidationBadges checks;
    lobes.set_materials(ui.preset, config.compare);
    checks.set_material(ui.preset);
    {
        GlTexture texture;
        RenderWorker worker(config.make_renderer, ui.view, config.chunk_seconds, config.max_samples);
        uint64_t submitted = 1;  // the worker's first generation is the initial state
        RenderFrame frame;
        std::vector<std::pair<uint64_t, Clock::time_point>> waiting;  // scripted changes not yet on screen
        Clock::time_point last = Clock::now(), script_end{};
        bool retone = false;
        int picked_x = -1, picked_y = -1;
        for (int n = 0; !glfwWindowShouldClose(window); ++n) {
            glfwPollEvents();
            bool changed = false;
            for (const ScriptedSet& s : config.sets) {
                if (s.frame != n) continue;
                ui.preset = with_parameter(ui.preset, s.key, s.value, "--set");
                ui.view.materials[size_t(config.edited_slot)] = ui.preset.material;
                changed = true;
            }
            if (changed) {
                submitted = worker.submit(ui.view);
                waiting.emplace_back(submitted, Clock::now());
                lobes.set_materials(ui.preset, config.compare);
                checks.set_material(ui.preset);
                changed = false;
            }
            if (worker.take_frame(&frame) || retone) {
                if (frame.image.valid()) texture.upload(film::to_srgb8(frame.image, ui.tone_map, ui.display_exposure), frame.image.width, frame.image.height);
                retone = false;
                for (auto it = waiting.begin(); it != waiting.end();) {
                    if (frame.generation >= it->first && frame.samples_per_pixel > 0) {
                        stats.change_seconds.push_back(seconds_between(it->second, Clock::now()));
                        it = waiting.erase(it);
                    } else {
                        ++it;
                    }
                }
            }

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            if (texture.width() > 0)
                ImGui::GetBackgroundDrawList()->AddImage(ImTextureID(intptr_t(texture.id())), ImVec2(0, 0),
                                                         ImVec2(float(texture.width()), float(texture.height())));
            if (!ImGui::GetIO().WantCaptureKeyboard) {
                if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) glfwSetWindowShouldClose(window, 1);
                if (ImGui::IsKeyPressed('R')) changed = true;
                if (ImGui::IsKeyPressed('B')) {
                    ui.view.show_background = !ui.view.show_background;
                    changed = true;
                }
            }
            changed |= mouse_on_render(&ui, config.width, config.height, &picked_x, &picked_y);
            if (picked_x >= 0)
                ImGui::GetForegroundDrawList()->AddRect(ImVec2(float(picked_x) - 2, float(picked_y) - 2), ImVec2(float(picked_x) + 3, float(picked_y) + 3),
                                                        IM_COL32(255, 255, 0, 255));
            ImGui::SetNextWindowPos(ImVec2(float(config.width), 0.0f));
            ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), float(window_height)));
            ImGui::Begin("dtoadq view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
            ImGui::Text("%d spp   %.3g samples/s", frame.samples_per_pixel, frame.samples_per_second);
            ImGui::TextWrapped("%s", worker.status().c_str());
            const std::string error = worker.error();
            if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error.c_str());
            if (!ui.message.empty()) ImGui::TextWrapped("%s", ui.message.c_str());
            if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
                if (material_panel(&ui.preset.material, config.preset.material)) {
                    ui.view.materials[size_t(config.edited_slot)] = ui.preset.material;
                    lobes.set_materials(ui.preset, config.compare);
                    checks.set_material(ui.preset);
                    changed = true;
                }
            }
            if (ImGui::CollapsingHeader("Checks", ImGuiTreeNodeFlags_DefaultOpen)) checks.draw();
            if (ImGui::CollapsingHeader("Lobe")) lobes.draw();
            if (ImGui::CollapsingHeader("Environment")) environment_panel(&ui, &changed, &retone);
            if (ImGui::CollapsingHeader("Presets")) preset_panel(&ui);
            if (ImGui::CollapsingHeader("Inspector")) inspector_panel(config, ui, frame, worker, picked_x, picked_y);
            if (ImGui::CollapsingHeader("Help")) help_panel();
            ImGui::End();
            if (changed) submitted = worker.submit(ui.view);  // shows from the worker's next chunk

            ImGui::Render();
            int fb_width = 0, fb_height = 0;
            glfwGetFramebufferSize(window, &fb_width, &fb_height);
            glViewport(0, 0, fb_width, fb_height);
            glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

            const Clock::time_point now = Clock::now();
            if (n > 0) stats.frame_seconds.push_back(seconds_between(last, now));
            last = now;
            if (headless && n + 1 >= config.frames) {
                // Done when the image shows the last state with enough samples.
                const bool current = frame.generation >= submitted && frame.samples_per_pixel >= config.min_samples;
                if (script_end == Clock::time_point{}) script_end = now;
                if (current || !worker.error().empty() || worker.status() == "no renderer") {
                    if (!config.screenshot.empty()) write_screenshot(config.screenshot, fb_width, fb_height);
                    glfwSwapBuffers(window);
                    std::printf("view: %d frames, %d spp, %.3g samples/s on %s\n", n + 1, frame.samples_per_pixel, frame.samples_per_second,
                                worker.device_description().c_str());
                    for (const std::array<int, 2>& px : config.inspect) {
                        std::string joined;
                        for (const std::string& l : inspect_pixel(config, ui, frame, worker, px[0], px[1])) joined += (joined.empty() ? "" : "; ") + l;
                        std::printf("inspect: %s\n", joined.c_str());
                    }
                    break;
                }
                if (seconds_between(script_end, now) > kScriptTimeoutSeconds) {
                    std::fprintf(stderr, "dtoadq: error: view: the image did not show the last change within %.0f s\n", kScriptTimeoutSeconds);
                    exit_status = 1;
                    break;
                }
            }
            glfwSwapBuffers(window);
        }
        const std::string error = worker.error();
        if (!error.empty()) {
            std::fprintf(stderr, "dtoadq: error: %s\n", error.c_str());
            exit_status = exit_status ? exit_status : 1;
        }
        if (config.stats) {
            // The checks of the last material, waited for (a run takes about a second).
            const Clock::time_point wait_start = Clock::now();
            while (checks.running() && seconds_between(wait_start, Clock::now()) < kScriptTimeoutSeconds)
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            std::printf("checks: %s\n", checks.summary().c_str());
        }
        if (config.stats) std::printf("%ssamples/s in the viewer: %.4g (at %d spp)\n", describe(stats).c_str(), frame.samples_per_second, frame.samples_per_pixel);
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);

    if (!config.save_preset.empty()) {
        brdf::save_preset(ui.preset, config.save_preset);
        std::printf("wrote %s\n", config.save_preset.c_str());
    }
    if (!config.export_scene.empty()) {
        export_to_scene(ui.preset, config.export_scene, config.export_name);
        std::printf("exported %s into %s\n", config.export_name.c_str(), config.export_scene.c_str());
    }
    return exit_status;
}

}  // namespace lab::viewer
