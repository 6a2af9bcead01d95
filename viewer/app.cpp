#include "viewer/app.hpp"

#include <algorithm>
#include <array>
#include <memory>
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
#include "viewer/panels.hpp"
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

constexpr int kPanelWidth = 440;
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
    ui.reference = config.preset;
    ui.preset.material = ui.view.materials.at(size_t(config.edited_slot));
    ui.tone_map = config.tone_map;
    ui.display_exposure = config.display_exposure;
    ui.split = config.split;

    // A scripted run lasts at least until its last --set has been applied.
    int last_frame = config.frames;
    for (const ScriptedSet& s : config.sets) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.moves) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.env_loads) last_frame = std::max(last_frame, s.frame + 1);
    int exit_status = 0;
    FrameStats stats;
    LobePanel lobes;
    ValidationBadges checks;
    lobes.set_materials(ui.preset, config.compare);
    checks.set_material(ui.preset);
    {
        GlTexture texture;
        RenderWorker::RendererFactory factory = config.make_renderer;
        auto worker = std::make_unique<RenderWorker>(factory, ui.view, config.chunk_seconds, config.max_samples);
        std::unique_ptr<RenderWorker> next_worker, worker_b;  // a new map being loaded; B of the split view
        RenderWorker::RendererFactory next_factory;
        GlTexture texture_b;
        RenderFrame frame_b;
        auto state_b = [&] {
            ViewState b = ui.view;
            b.materials[size_t(config.edited_slot)] = config.compare.material;
            return b;
        };
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
                lobes.set_materials(ui.preset, config.compare);
                checks.set_material(ui.preset);
            }
            bool moved = false;  // the camera or environment: B's view changes too
            for (const ScriptedSet& s : config.moves) {
                if (s.frame != n) continue;
                apply_move(&ui.view, s.key, s.value);
                moved = true;
            }
            if (changed || moved) {
                submitted = worker->submit(ui.view);
                if (worker_b && moved) worker_b->submit(state_b());
                waiting.emplace_back(submitted, Clock::now());
                changed = false;
            }
            // A new map: the old renderer shows until the new one is ready; a failure keeps the old.
            if (next_worker && next_worker->ready()) {
                worker = std::move(next_worker);
                factory = next_factory;
                frame.sequence = 0;
                if (worker_b) {
                    worker_b = std::make_unique<RenderWorker>(factory, state_b(), config.chunk_seconds, config.max_samples);
                    frame_b.sequence = 0;
                }
                submitted = worker->submit(ui.view);
            } else if (next_worker && next_worker->status() == "no renderer") {
                ui.message = next_worker->error();
                next_worker.reset();
            }
            if (ui.split && !worker_b) {
                worker_b = std::make_unique<RenderWorker>(factory, state_b(), config.chunk_seconds, config.max_samples);
                frame_b = RenderFrame{};
            } else if (!ui.split && worker_b) {
                worker_b.reset();
            }
            if (worker_b && (worker_b->take_frame(&frame_b) || retone) && frame_b.image.valid())
                texture_b.upload(film::to_srgb8(frame_b.image, ui.tone_map, ui.display_exposure), frame_b.image.width, frame_b.image.height);
            if (worker->take_frame(&frame) || retone) {
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
            if (texture.width() > 0) {
                const float w = float(texture.width()), h = float(texture.height());
                const float split = worker_b && texture_b.width() == texture.width() ? ui.split_x : 1.0f;
                ImDrawList* back = ImGui::GetBackgroundDrawList();
                back->AddImage(ImTextureID(intptr_t(texture.id())), ImVec2(0, 0), ImVec2(w * split, h), ImVec2(0, 0), ImVec2(split, 1));
                if (split < 1.0f) {
                    back->AddImage(ImTextureID(intptr_t(texture_b.id())), ImVec2(w * split, 0), ImVec2(w, h), ImVec2(split, 0), ImVec2(1, 1));
                    back->AddLine(ImVec2(w * split, 0), ImVec2(w * split, h), IM_COL32(255, 255, 255, 200), 2.0f);
                    back->AddText(ImVec2(4, h - 16), IM_COL32(255, 255, 255, 255), "A");
                    back->AddText(ImVec2(w - 12, h - 16), IM_COL32(255, 255, 255, 255), "B");
                }
            }
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
            ImGui::Text("%d spp   %.3g samples/s%s", frame.samples_per_pixel, frame.samples_per_second, frame.scale > 1 ? "   (first pass, reduced)" : "");
            if (worker_b) {
                ImGui::SameLine();
                ImGui::Text("   B: %d spp", frame_b.samples_per_pixel);
            }
            ImGui::Checkbox("A/B split view (B: --compare)", &ui.split);
            if (next_worker) ImGui::TextUnformatted("loading the environment map...");
            ImGui::TextWrapped("%s", worker->status().c_str());
            const std::string error = worker->error();
            if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error.c_str());
            if (!ui.message.empty()) ImGui::TextWrapped("%s", ui.message.c_str());
            if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
                if (material_panel(&ui.preset.material, ui.reference.material)) {
                    ui.view.materials[size_t(config.edited_slot)] = ui.preset.material;
                    lobes.set_materials(ui.preset, config.compare);
                    checks.set_material(ui.preset);
                    changed = true;
                }
            }
            if (ImGui::CollapsingHeader("Checks", ImGuiTreeNodeFlags_DefaultOpen)) checks.draw();
            if (ImGui::CollapsingHeader("Lobe")) lobes.draw();
            std::string load_env;
            if (ImGui::CollapsingHeader("Environment")) environment_panel(&ui, &changed, &retone, &load_env);
            for (const ScriptedSet& s : config.env_loads)
                if (s.frame == n) load_env = s.value;
            if (!load_env.empty() && config.factory_for_env) {
                next_factory = config.factory_for_env(load_env);
                next_worker = std::make_unique<RenderWorker>(next_factory, ui.view, config.chunk_seconds, config.max_samples);
                ui.message.clear();
            }
            if (ImGui::CollapsingHeader("Presets") && preset_panel(&ui)) {
                ui.view.materials[size_t(config.edited_slot)] = ui.preset.material;
                lobes.set_materials(ui.preset, config.compare);
                checks.set_material(ui.preset);
                changed = true;
            }
            if (ImGui::CollapsingHeader("Inspector")) inspector_panel(config, ui, frame, *worker, picked_x, picked_y);
            if (ImGui::CollapsingHeader("Help")) help_panel();
            ImGui::End();
            if (changed) {
                submitted = worker->submit(ui.view);  // shows from the worker's next chunk
                if (worker_b) worker_b->submit(state_b());
            }

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
            if (headless && n + 1 >= last_frame) {
                // Done when the image shows the last state with enough samples.
                const bool current = frame.generation >= submitted && frame.scale == 1 && frame.samples_per_pixel >= config.min_samples &&
                                     (!worker_b || (frame_b.scale == 1 && frame_b.samples_per_pixel >= config.min_samples)) && !next_worker;
                if (script_end == Clock::time_point{}) script_end = now;
                if (current || !worker->error().empty() || worker->status() == "no renderer") {
                    if (!config.screenshot.empty()) write_screenshot(config.screenshot, fb_width, fb_height);
                    glfwSwapBuffers(window);
                    std::printf("view: %d frames, %d spp, %.3g samples/s on %s\n", n + 1, frame.samples_per_pixel, frame.samples_per_second,
                                worker->device_description().c_str());
                    if (!ui.message.empty()) std::printf("view: message: %s\n", ui.message.c_str());
                    for (const std::array<int, 2>& px : config.inspect) {
                        std::string joined;
                        for (const std::string& l : inspect_pixel(config, ui, frame, *worker, px[0], px[1])) joined += (joined.empty() ? "" : "; ") + l;
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
        const std::string error = worker->error();
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
