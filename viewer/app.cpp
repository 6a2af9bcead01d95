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

// The window with its OpenGL 3.0 context and Dear ImGui, closed in the reverse order.
class ViewerWindow {
public:
    ViewerWindow(const ViewerConfig& config, bool headless) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        const int window_width = config.width + kPanelWidth;
        height_ = config.height > kMinWindowHeight ? config.height : kMinWindowHeight;
        if (headless) glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        window_ = glfwCreateWindow(window_width, height_, config.title.c_str(), nullptr, nullptr);
        if (!window_) throw std::runtime_error("cannot open a window (no OpenGL 3.0 context?): GLFW " + g_glfw_error);
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(headless ? 0 : 1);  // headless frames are not paced by a display

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window_, true);
        ImGui_ImplOpenGL3_Init("#version 130");
    }
    ~ViewerWindow() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        glfwDestroyWindow(window_);
    }
    ViewerWindow(const ViewerWindow&) = delete;
    ViewerWindow& operator=(const ViewerWindow&) = delete;

    GLFWwindow* get() const { return window_; }
    int height() const { return height_; }

private:
    GlfwSession glfw_;  // first: GLFW starts before the window opens and ends after it closes
    GLFWwindow* window_ = nullptr;
    int height_ = 0;
};

UiState initial_ui_state(const ViewerConfig& config) {
    UiState ui;
    ui.view = config.initial;
    ui.preset = config.preset;
    ui.reference = config.preset;
    ui.preset.material = ui.view.materials.at(size_t(config.edited_slot));
    ui.tone_map = config.tone_map;
    ui.display_exposure = config.display_exposure;
    ui.split = config.split;
    return ui;
}

// A scripted run lasts at least until its last --set, --move and --load-env have been applied.
int last_scripted_frame(const ViewerConfig& config) {
    int last_frame = config.frames;
    for (const ScriptedSet& s : config.sets) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.moves) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.env_loads) last_frame = std::max(last_frame, s.frame + 1);
    return last_frame;
}

// The frame loop: the render workers (A, B of the split view, and one under a new environment map
// while it loads) with their latest frames and textures, the panels, and the script's progress.
class FrameLoop {
public:
    FrameLoop(const ViewerConfig& config, const ViewerWindow& window, UiState* ui)
        : config_(config), window_(window), ui_(*ui), headless_(config.frames > 0), last_frame_(last_scripted_frame(config)),
          factory_(config.make_renderer) {
        lobes_.set_materials(ui_.preset, config_.compare);
        checks_.set_material(ui_.preset);
        worker_ = std::make_unique<RenderWorker>(factory_, ui_.view, config_.chunk_seconds, config_.max_samples);
    }

    // Until the window closes or the script ends; returns the exit status.
    int run() {
        for (int n = 0; !glfwWindowShouldClose(window_.get()); ++n) {
            glfwPollEvents();
            apply_script(n);
            follow_workers();
            show_frames();

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            draw_render();
            bool changed = handle_keys_and_mouse();
            changed |= draw_panels(n);
            if (changed) {
                submitted_ = worker_->submit(ui_.view);  // shows from the worker's next chunk
                if (worker_b_) worker_b_->submit(state_b());
            }

            ImGui::Render();
            int fb_width = 0, fb_height = 0;
            glfwGetFramebufferSize(window_.get(), &fb_width, &fb_height);
            glViewport(0, 0, fb_width, fb_height);
            glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

            const Clock::time_point now = Clock::now();
            if (n > 0) stats_.frame_seconds.push_back(seconds_between(last_, now));
            last_ = now;
            if (headless_ && n + 1 >= last_frame_ && script_ended(n, now, fb_width, fb_height)) break;
            glfwSwapBuffers(window_.get());
        }
        report();
        return exit_status_;
    }

private:
    ViewState state_b() const {
        ViewState b = ui_.view;
        b.materials[size_t(config_.edited_slot)] = config_.compare.material;
        return b;
    }

    // ui_.preset changed: the render, the lobes and the checks follow it.
    void material_edited() {
        ui_.view.materials[size_t(config_.edited_slot)] = ui_.preset.material;
        lobes_.set_materials(ui_.preset, config_.compare);
        checks_.set_material(ui_.preset);
    }

    // The --set and --move changes of frame n, submitted at once and timed until they show.
    void apply_script(int n) {
        bool changed = false;
        for (const ScriptedSet& s : config_.sets) {
            if (s.frame != n) continue;
            ui_.preset = with_parameter(ui_.preset, s.key, s.value, "--set");
            changed = true;
        }
        if (changed) material_edited();
        bool moved = false;  // the camera or environment: B's view changes too
        for (const ScriptedSet& s : config_.moves) {
            if (s.frame != n) continue;
            apply_move(&ui_.view, s.key, s.value);
            moved = true;
        }
        if (changed || moved) {
            submitted_ = worker_->submit(ui_.view);
            if (worker_b_ && moved) worker_b_->submit(state_b());
            waiting_.emplace_back(submitted_, Clock::now());
        }
    }

    // A new map: the old renderer shows until the new one is ready; a failure keeps the old. B
    // runs while the split view is on.
    void follow_workers() {
        if (next_worker_ && next_worker_->ready()) {
            worker_ = std::move(next_worker_);
            factory_ = next_factory_;
            frame_.sequence = 0;
            if (worker_b_) {
                worker_b_ = std::make_unique<RenderWorker>(factory_, state_b(), config_.chunk_seconds, config_.max_samples);
                frame_b_.sequence = 0;
            }
            submitted_ = worker_->submit(ui_.view);
        } else if (next_worker_ && next_worker_->status() == "no renderer") {
            ui_.message = next_worker_->error();
            next_worker_.reset();
        }
        if (ui_.split && !worker_b_) {
            worker_b_ = std::make_unique<RenderWorker>(factory_, state_b(), config_.chunk_seconds, config_.max_samples);
            frame_b_ = RenderFrame{};
        } else if (!ui_.split && worker_b_) {
            worker_b_.reset();
        }
    }

    // The workers' latest frames into the textures (again when the tone map changed); a change is
    // on screen once a frame of its generation has samples.
    void show_frames() {
        if (worker_b_ && (worker_b_->take_frame(&frame_b_) || retone_) && frame_b_.image.valid())
            texture_b_.upload(film::to_srgb8(frame_b_.image, ui_.tone_map, ui_.display_exposure), frame_b_.image.width, frame_b_.image.height);
        if (worker_->take_frame(&frame_) || retone_) {
            if (frame_.image.valid()) texture_.upload(film::to_srgb8(frame_.image, ui_.tone_map, ui_.display_exposure), frame_.image.width, frame_.image.height);
            retone_ = false;
            for (auto it = waiting_.begin(); it != waiting_.end();) {
                if (frame_.generation >= it->first && frame_.samples_per_pixel > 0) {
                    stats_.change_seconds.push_back(seconds_between(it->second, Clock::now()));
                    it = waiting_.erase(it);
                } else {
                    ++it;
                }
            }
        }
    }

    // The render behind the panels: A, and B right of the divider in the split view.
    void draw_render() const {
        if (texture_.width() <= 0) return;
        const float w = float(texture_.width()), h = float(texture_.height());
        const float split = worker_b_ && texture_b_.width() == texture_.width() ? ui_.split_x : 1.0f;
        ImDrawList* back = ImGui::GetBackgroundDrawList();
        back->AddImage(ImTextureID(intptr_t(texture_.id())), ImVec2(0, 0), ImVec2(w * split, h), ImVec2(0, 0), ImVec2(split, 1));
        if (split < 1.0f) {
            back->AddImage(ImTextureID(intptr_t(texture_b_.id())), ImVec2(w * split, 0), ImVec2(w, h), ImVec2(split, 0), ImVec2(1, 1));
            back->AddLine(ImVec2(w * split, 0), ImVec2(w * split, h), IM_COL32(255, 255, 255, 200), 2.0f);
            back->AddText(ImVec2(4, h - 16), IM_COL32(255, 255, 255, 255), "A");
            back->AddText(ImVec2(w - 12, h - 16), IM_COL32(255, 255, 255, 255), "B");
        }
    }

    // Escape, R (restart), B (background) and the mouse on the render; returns whether the view changed.
    bool handle_keys_and_mouse() {
        bool changed = false;
        if (!ImGui::GetIO().WantCaptureKeyboard) {
            if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) glfwSetWindowShouldClose(window_.get(), 1);
            if (ImGui::IsKeyPressed('R')) changed = true;
            if (ImGui::IsKeyPressed('B')) {
                ui_.view.show_background = !ui_.view.show_background;
                changed = true;
            }
        }
        changed |= mouse_on_render(&ui_, config_.width, config_.height, &picked_x_, &picked_y_);
        if (picked_x_ >= 0)
            ImGui::GetForegroundDrawList()->AddRect(ImVec2(float(picked_x_) - 2, float(picked_y_) - 2),
                                                    ImVec2(float(picked_x_) + 3, float(picked_y_) + 3), IM_COL32(255, 255, 0, 255));
        return changed;
    }

    // The panel window beside the render; returns whether the view changed. A map to load (from the
    // environment panel or the script's --load-env of frame n) starts its worker.
    bool draw_panels(int n) {
        bool changed = false;
        ImGui::SetNextWindowPos(ImVec2(float(config_.width), 0.0f));
        ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), float(window_.height())));
        ImGui::Begin("dtoadq view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::Text("%d spp   %.3g samples/s%s", frame_.samples_per_pixel, frame_.samples_per_second, frame_.scale > 1 ? "   (first pass, reduced)" : "");
        if (worker_b_) {
            ImGui::SameLine();
            ImGui::Text("   B: %d spp", frame_b_.samples_per_pixel);
        }
        ImGui::Checkbox("A/B split view (B: --compare)", &ui_.split);
        if (next_worker_) ImGui::TextUnformatted("loading the environment map...");
        ImGui::TextWrapped("%s", worker_->status().c_str());
        const std::string error = worker_->error();
        if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error.c_str());
        if (!ui_.message.empty()) ImGui::TextWrapped("%s", ui_.message.c_str());
        if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
            if (material_panel(&ui_.preset.material, ui_.reference.material)) {
                material_edited();
                changed = true;
            }
        }
        if (ImGui::CollapsingHeader("Checks", ImGuiTreeNodeFlags_DefaultOpen)) checks_.draw();
        if (ImGui::CollapsingHeader("Lobe")) lobes_.draw();
        std::string load_env;
        if (ImGui::CollapsingHeader("Environment")) environment_panel(&ui_, &changed, &retone_, &load_env);
        for (const ScriptedSet& s : config_.env_loads)
            if (s.frame == n) load_env = s.value;
        if (!load_env.empty() && config_.factory_for_env) {
            next_factory_ = config_.factory_for_env(load_env);
            next_worker_ = std::make_unique<RenderWorker>(next_factory_, ui_.view, config_.chunk_seconds, config_.max_samples);
            ui_.message.clear();
        }
        if (ImGui::CollapsingHeader("Presets") && preset_panel(&ui_)) {
            material_edited();
            changed = true;
        }
        if (ImGui::CollapsingHeader("Inspector")) inspector_panel(config_, ui_, frame_, *worker_, picked_x_, picked_y_);
        if (ImGui::CollapsingHeader("Help")) help_panel();
        ImGui::End();
        return changed;
    }

    // A headless run ends once the image shows the last state with enough samples (the screenshot,
    // the summary and the inspected pixels are written then), or fails when it has not within
    // kScriptTimeoutSeconds. Returns whether it ended.
    bool script_ended(int n, Clock::time_point now, int fb_width, int fb_height) {
        const bool current = frame_.generation >= submitted_ && frame_.scale == 1 && frame_.samples_per_pixel >= config_.min_samples &&
                             (!worker_b_ || (frame_b_.scale == 1 && frame_b_.samples_per_pixel >= config_.min_samples)) && !next_worker_;
        if (script_end_ == Clock::time_point{}) script_end_ = now;
        if (current || !worker_->error().empty() || worker_->status() == "no renderer") {
            if (!config_.screenshot.empty()) write_screenshot(config_.screenshot, fb_width, fb_height);
            glfwSwapBuffers(window_.get());
            std::printf("view: %d frames, %d spp, %.3g samples/s on %s\n", n + 1, frame_.samples_per_pixel, frame_.samples_per_second,
                        worker_->device_description().c_str());
            if (!ui_.message.empty()) std::printf("view: message: %s\n", ui_.message.c_str());
            for (const std::array<int, 2>& px : config_.inspect) {
                std::string joined;
                for (const std::string& l : inspect_pixel(config_, ui_, frame_, *worker_, px[0], px[1])) joined += (joined.empty() ? "" : "; ") + l;
                std::printf("inspect: %s\n", joined.c_str());
            }
            return true;
        }
        if (seconds_between(script_end_, now) > kScriptTimeoutSeconds) {
            std::fprintf(stderr, "dtoadq: error: view: the image did not show the last change within %.0f s\n", kScriptTimeoutSeconds);
            exit_status_ = 1;
            return true;
        }
        return false;
    }

    // After the loop: the render's error, and with --stats the checks and the frame times.
    void report() {
        const std::string error = worker_->error();
        if (!error.empty()) {
            std::fprintf(stderr, "dtoadq: error: %s\n", error.c_str());
            exit_status_ = exit_status_ ? exit_status_ : 1;
        }
        if (config_.stats) {
            // The checks of the last material, waited for (a run takes about a second).
            const Clock::time_point wait_start = Clock::now();
            while (checks_.running() && seconds_between(wait_start, Clock::now()) < kScriptTimeoutSeconds)
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            std::printf("checks: %s\n", checks_.summary().c_str());
        }
        if (config_.stats)
            std::printf("%ssamples/s in the viewer: %.4g (at %d spp)\n", describe(stats_).c_str(), frame_.samples_per_second, frame_.samples_per_pixel);
    }

    const ViewerConfig& config_;
    const ViewerWindow& window_;
    UiState& ui_;
    const bool headless_;
    const int last_frame_;
    int exit_status_ = 0;
    FrameStats stats_;
    LobePanel lobes_;
    ValidationBadges checks_;
    GlTexture texture_, texture_b_;
    RenderWorker::RendererFactory factory_, next_factory_;
    std::unique_ptr<RenderWorker> worker_;
    std::unique_ptr<RenderWorker> next_worker_, worker_b_;  // a new map being loaded; B of the split view
    RenderFrame frame_, frame_b_;
    uint64_t submitted_ = 1;  // the worker's first generation is the initial state
    std::vector<std::pair<uint64_t, Clock::time_point>> waiting_;  // scripted changes not yet on screen
    Clock::time_point last_ = Clock::now(), script_end_{};
    bool retone_ = false;
    int picked_x_ = -1, picked_y_ = -1;
};

// What the script asked to write on exit: the edited preset, and the material exported to a scene.
void write_outputs(const ViewerConfig& config, const UiState& ui) {
    if (!config.save_preset.empty()) {
        brdf::save_preset(ui.preset, config.save_preset);
        std::printf("wrote %s\n", config.save_preset.c_str());
    }
    if (!config.export_scene.empty()) {
        export_to_scene(ui.preset, config.export_scene, config.export_name);
        std::printf("exported %s into %s\n", config.export_name.c_str(), config.export_scene.c_str());
    }
}

}  // namespace

int run_viewer(const ViewerConfig& config) {
    UiState ui;
    int exit_status = 0;
    {
        ViewerWindow window(config, config.frames > 0);
        ui = initial_ui_state(config);
        FrameLoop loop(config, window, &ui);
        exit_status = loop.run();
    }
    write_outputs(config, ui);
    return exit_status;
}

}  // namespace lab::viewer
