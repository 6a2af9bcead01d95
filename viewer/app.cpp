#include "viewer/app.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
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
#include "render/render_settings.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/panels.hpp"
#include "viewer/gl_image.hpp"
#include "viewer/lobe_panel.hpp"
#include "viewer/material_edit.hpp"
#include "viewer/material_panel.hpp"
#include "viewer/pixel_probe.hpp"
#include "viewer/material_export.hpp"
#include "viewer/scene_export.hpp"
#include "viewer/validation_badges.hpp"
#include "viewer/view_export.hpp"
#include "viewer/view_menu.hpp"
#include "viewer/view_modes.hpp"
#include "viewer/window_layout.hpp"

namespace lab::viewer {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The window's first height at least.
constexpr int kMinWindowHeight = 560;
// An open panel section is never squeezed below this; its content scrolls inside it.
constexpr float kMinSectionHeight = 90.0f;
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
        const int width = config.window_width > 0 ? config.window_width : config.width + kPanelColumnWidth;
        const int height = config.window_height > 0 ? config.window_height : std::max(config.height, kMinWindowHeight);
        window_ = glfwCreateWindow(width, height, config.title.c_str(), nullptr, nullptr);
        if (!window_) throw std::runtime_error("cannot open a window (no OpenGL 3.0 context?): GLFW " + g_glfw_error);
        glfwSetWindowSizeLimits(window_, kSmallestWindowWidth, kSmallestWindowHeight, GLFW_DONT_CARE, GLFW_DONT_CARE);
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

private:
    GlfwSession glfw_;  // first: GLFW starts before the window opens and ends after it closes
    GLFWwindow* window_ = nullptr;
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
    ui.denoise = config.denoise;
    return ui;
}

// A scripted run lasts at least until its last --set, --move and --load-env have been applied.
int last_scripted_frame(const ViewerConfig& config) {
    int last_frame = config.frames;
    for (const ScriptedSet& s : config.sets) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.moves) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.env_loads) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.reference_loads) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.resizes) last_frame = std::max(last_frame, s.frame + 1);
    for (const ScriptedSet& s : config.view_modes) last_frame = std::max(last_frame, s.frame + 1);
    return last_frame;
}

// A section of the panel: its header, and its body in a scroll area of its own, sized by share_heights.
struct PanelSection {
    PanelSection(const char* section_name, int column, bool open_at_start) : name(section_name), column_of_two(column), open(open_at_start) {}
    const char* name;
    int column_of_two;   // where it goes when the panel has two columns
    bool open;
    float wanted = 240.0f;  // the body's content height, as measured when last drawn
    Rect rect;              // the body's scroll area on screen, as last drawn
};

enum SectionId { kMaterial, kChecks, kLobe, kEnvironment, kPresets, kInspector, kHelp, kSectionCount };

std::vector<PanelSection> panel_sections(const std::vector<std::string>& open) {
    std::vector<PanelSection> sections = {{"Material", 0, true},  {"Checks", 1, true},    {"Lobe", 1, false}, {"Environment", 0, false},
                                          {"Presets", 0, false}, {"Inspector", 1, false}, {"Help", 1, false}};
    for (PanelSection& s : sections)
        for (const std::string& name : open) s.open |= name == "all" || name == s.name;
    return sections;
}

// The frame loop: the render workers (A, B of the split view, and one under a new environment map
// while it loads) with their latest frames and textures, the panels, and the script's progress.
class FrameLoop {
public:
    FrameLoop(const ViewerConfig& config, const ViewerWindow& window, UiState* ui)
        : config_(config), window_(window), ui_(*ui), headless_(config.frames > 0), last_frame_(last_scripted_frame(config)),
          factory_(config.make_renderer), sections_(panel_sections(config.open_sections)) {
        lobes_.set_materials(ui_.preset, config_.compare);
        checks_.set_material(ui_.preset);
        worker_ = new_worker(factory_, ui_.view);
    }

    // Until the window closes or the script ends; returns the exit status.
    int run() {
        for (int n = 0; !glfwWindowShouldClose(window_.get()); ++n) {
            glfwPollEvents();
            apply_script(n);
            follow_workers();
            want_views();
            show_frames();
            save_pending_exr();

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            bool changed = follow_window();
            draw_render();
            changed |= handle_keys_and_mouse();
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
            if (ui_.denoise) waiting_denoised_.emplace_back(submitted_, Clock::now());
        }
        for (const ScriptedSet& s : config_.view_modes)
            if (s.frame == n) {
                view_mode_ = parse_view_mode(s.value, "--view-mode");  // checked before the window opened
                retone_ = true;
            }
        for (const ScriptedSet& s : config_.resizes) {
            if (s.frame != n) continue;
            int w = 0, h = 0;
            render::parse_image_size(s.value, "--resize", &w, &h);  // checked before the window opened
            glfwSetWindowSize(window_.get(), w, h);
            resize_pending_ = {w, h};
        }
    }

    // The layout of the window as it is now; a new render area sets the render's size (or only the
    // display's scale). Returns whether the render's size changed. With --print-layout each new
    // layout is printed.
    bool follow_window() {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        LayoutRequest request;
        request.window_width = int(display.x);
        request.window_height = int(display.y);
        request.aspect_width = config_.width;
        request.aspect_height = config_.height;
        request.sizing = sizing_;
        request.fixed_width = config_.width;
        request.fixed_height = config_.height;
        request.max_render_pixels = config_.max_render_pixels;
        layout_ = layout_window(request);
        if (resize_pending_[0] == request.window_width && resize_pending_[1] == request.window_height) resize_pending_ = {0, 0};
        if (config_.print_layout) {
            const std::string line = describe_layout(layout_, request.window_width, request.window_height);
            if (line != layout_printed_) std::printf("%s\n", line.c_str());
            layout_printed_ = line;
        }
        if (layout_.render_width == ui_.view.width && layout_.render_height == ui_.view.height) return false;
        ui_.view.width = layout_.render_width;
        ui_.view.height = layout_.render_height;
        if (picked_x_ >= layout_.render_width || picked_y_ >= layout_.render_height) picked_x_ = picked_y_ = -1;
        return true;
    }

    // The view state for a worker rendering `s`: the edited slots of the scene, then the look-dev
    // references' own (their slots come last: scene/look_dev_references.hpp).
    ViewState view_for(const scene::Scene& s) const {
        ViewState v = ui_.view;
        v.materials.resize(config_.base_scene.materials.size());
        for (size_t i = v.materials.size(); i < s.materials.size(); ++i) v.materials.push_back(s.materials[i].material);
        return v;
    }

    // A worker for `state` that denoises its display as the panel says.
    std::unique_ptr<RenderWorker> new_worker(const RenderWorker::RendererFactory& factory, const ViewState& state) const {
        auto worker = std::make_unique<RenderWorker>(factory, state, config_.chunk_seconds, config_.max_samples);
        worker->set_denoise(ui_.denoise);
        return worker;
    }

    // A renderer under another map or with other references, made on a worker of its own while the
    // current one keeps showing.
    void start_next_worker(const std::string& env, const scene::LookDevReferences& references) {
        if (!config_.factory_for) return;
        next_env_ = env;
        next_references_ = references;
        next_scene_ = scene::with_look_dev_references(config_.base_scene, references, float(config_.width) / float(config_.height));
        next_factory_ = config_.factory_for(env, references);
        next_worker_ = new_worker(next_factory_, view_for(next_scene_));
        ui_.message.clear();
    }

    // The display's denoising on or off, for every worker (the film is not touched: no restart).
    void set_denoise(bool on) {
        for (RenderWorker* w : {worker_.get(), worker_b_.get(), next_worker_.get()})
            if (w) w->set_denoise(on);
    }

    // A new map or new references: the old renderer shows until the new one is ready; a failure
    // keeps the old. B runs while the split view is on.
    void follow_workers() {
        if (next_worker_ && next_worker_->ready()) {
            worker_ = std::move(next_worker_);
            factory_ = next_factory_;
            scene_ = next_scene_;
            references_ = next_references_;
            env_ = next_env_;
            ui_.view = view_for(scene_);  // the edits made while it loaded, its own references
            frame_.sequence = 0;
            if (worker_b_) {
                worker_b_ = new_worker(factory_, state_b());
                frame_b_.sequence = 0;
            }
            submitted_ = worker_->submit(ui_.view);
        } else if (next_worker_ && next_worker_->status() == "no renderer") {
            ui_.message = next_worker_->error();
            next_worker_.reset();
            shown_references_ = references_;  // the boxes show what is rendered
        }
        if (ui_.split && !worker_b_) {
            worker_b_ = new_worker(factory_, state_b());
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
            if (frame_.image.valid()) {
                const Clock::time_point start = Clock::now();
                texture_.upload(view_of(frame_), frame_.image.width, frame_.image.height);
                stats_.display_seconds.push_back(seconds_between(start, Clock::now()));
                stats_.display_pixels.push_back(double(frame_.image.width) * double(frame_.image.height));
            }
            retone_ = false;
            // a change is shown by a frame of its generation or a later one
            const auto shown = [&](std::vector<std::pair<uint64_t, Clock::time_point>>* waiting, bool showing, std::vector<double>* latencies) {
                for (auto it = waiting->begin(); it != waiting->end();) {
                    if (showing && frame_.generation >= it->first) {
                        latencies->push_back(seconds_between(it->second, Clock::now()));
                        it = waiting->erase(it);
                    } else {
                        ++it;
                    }
                }
            };
            shown(&waiting_, frame_.samples_per_pixel > 0, &stats_.change_seconds);
            shown(&waiting_denoised_, frame_.denoised_samples > 0, &stats_.denoised_seconds);
        }
    }

    // What the view, a pending "save EXR" and the script's --save-exr need of the worker.
    void want_views() {
        render::AovSelection layers = config_.save_layers;
        if (pending_exr_) {
            const render::AovSelection& p = pending_exr_->second;
            layers.albedo |= p.albedo, layers.normal |= p.normal, layers.depth |= p.depth, layers.slot |= p.slot;
            layers.variance |= p.variance, layers.samples |= p.samples;
        }
        worker_->want_views(needs_film_statistics(view_mode_) || layers.variance || layers.samples,
                            needs_first_hits(view_mode_) || layers.first_hit());
    }

    // The panel's "save EXR" once the frame holds its layers (they are asked for when it is pressed).
    void save_pending_exr() {
        if (!pending_exr_ || !frame_has_layers(frame_, pending_exr_->second)) return;
        try {
            save_frame_exr(pending_exr_->first, frame_, pending_exr_->second, ui_.tone_map, ui_.display_exposure);
            ui_.message = "wrote " + pending_exr_->first;
        } catch (const std::exception& e) {
            ui_.message = e.what();
        }
        pending_exr_.reset();
    }

    // The frame as the view menu's choice shows it; the image itself while the view's inputs are
    // not there yet (view_shown_ says which).
    std::vector<uint8_t> view_of(const RenderFrame& frame) {
        ViewInputs in;
        in.image = &frame.image;
        in.first_hits = frame.first_hits.get();
        in.variance = &frame.variance;
        in.samples = &frame.samples;
        in.tone_map = ui_.tone_map;
        in.exposure_stops = ui_.display_exposure;
        in.relative_error_threshold = error_threshold_;
        std::vector<uint8_t> bytes = view_pixels(view_mode_, in);
        view_shown_ = !bytes.empty();
        return view_shown_ ? bytes : film::to_srgb8(frame.image, ui_.tone_map, ui_.display_exposure);
    }

    // The render in its rectangle of the render area (scaled when the render's size differs): A,
    // and B right of the divider in the split view.
    void draw_render() const {
        if (texture_.width() <= 0) return;
        const Rect& r = layout_.image;
        const float split = worker_b_ && texture_b_.width() == texture_.width() ? ui_.split_x : 1.0f;
        const float divider = r.x + r.w * split;
        ImDrawList* back = ImGui::GetBackgroundDrawList();
        back->AddImage(ImTextureID(intptr_t(texture_.id())), ImVec2(r.x, r.y), ImVec2(divider, r.bottom()), ImVec2(0, 0), ImVec2(split, 1));
        if (split < 1.0f) {
            back->AddImage(ImTextureID(intptr_t(texture_b_.id())), ImVec2(divider, r.y), ImVec2(r.right(), r.bottom()), ImVec2(split, 0),
                           ImVec2(1, 1));
            back->AddLine(ImVec2(divider, r.y), ImVec2(divider, r.bottom()), IM_COL32(255, 255, 255, 200), 2.0f);
            back->AddText(ImVec2(r.x + 4, r.bottom() - 16), IM_COL32(255, 255, 255, 255), "A");
            back->AddText(ImVec2(r.right() - 12, r.bottom() - 16), IM_COL32(255, 255, 255, 255), "B");
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
        const Rect& r = layout_.image;
        changed |= mouse_on_render(&ui_, r, layout_.render_width, layout_.render_height, &picked_x_, &picked_y_);
        if (picked_x_ >= 0) {  // the picked pixel's centre on screen
            const float x = r.x + (float(picked_x_) + 0.5f) * r.w / float(layout_.render_width);
            const float y = r.y + (float(picked_y_) + 0.5f) * r.h / float(layout_.render_height);
            ImGui::GetForegroundDrawList()->AddRect(ImVec2(x - 2.5f, y - 2.5f), ImVec2(x + 2.5f, y + 2.5f), IM_COL32(255, 255, 0, 255));
        }
        return changed;
    }

    // The panel window beside the render, in one or two columns of sections; returns whether the
    // view changed. A map to load (from the environment panel or the script's --load-env of frame n)
    // starts its worker.
    bool draw_panels(int n) {
        bool changed = false;
        const Rect& p = layout_.panel;
        ImGui::SetNextWindowPos(ImVec2(p.x, p.y));
        ImGui::SetNextWindowSize(ImVec2(p.w, p.h));
        ImGui::Begin("dtoadq view", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar |
                         ImGuiWindowFlags_NoScrollWithMouse);
        ImGui::Text("%d spp   %.3g samples/s%s", frame_.samples_per_pixel, frame_.samples_per_second, frame_.scale > 1 ? "   (first pass, reduced)" : "");
        if (frame_.denoised_samples > 0) {
            ImGui::SameLine();
            ImGui::Text("   denoised from %d spp", frame_.denoised_samples);
        }
        if (worker_b_) {
            ImGui::SameLine();
            ImGui::Text("   B: %d spp", frame_b_.samples_per_pixel);
        }
        ImGui::Checkbox("A/B split view (B: --compare)", &ui_.split);
        ImGui::SameLine();
        if (ImGui::Checkbox("denoise", &ui_.denoise)) set_denoise(ui_.denoise);
        int sizing = int(sizing_);
        ImGui::SetNextItemWidth(150.0f);
        if (ImGui::Combo("window size changes", &sizing, "the render's size\0the display's scale\0")) sizing_ = DisplaySizing(sizing);
        ImGui::SameLine();
        ImGui::Text("render %dx%d", layout_.render_width, layout_.render_height);
        retone_ |= view_menu(&view_mode_, &error_threshold_);
        if (save_exr_controls(exr_path_, sizeof exr_path_, exr_layers_, sizeof exr_layers_)) {
            try {
                pending_exr_.emplace(exr_path_, render::parse_aov_selection(exr_layers_, exr_path_, "save EXR"));
                ui_.message = "saving " + std::string(exr_path_) + " once the frame has its layers";
            } catch (const std::exception& e) {
                ui_.message = e.what();
            }
        }
        if (!view_shown_) ImGui::TextUnformatted("(the view's inputs are on their way: the image meanwhile)");
        if (next_worker_) ImGui::TextUnformatted("loading the environment map...");
        ImGui::TextWrapped("%s", worker_->status().c_str());
        const std::string error = worker_->error();
        if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error.c_str());
        if (!ui_.message.empty()) ImGui::TextWrapped("%s", ui_.message.c_str());

        std::string load_env;
        const float spacing = ImGui::GetStyle().ItemSpacing.x;
        const ImVec2 avail = ImGui::GetContentRegionAvail();
        const float column_width = (avail.x - spacing * float(layout_.columns - 1)) / float(layout_.columns);
        for (int c = 0; c < layout_.columns; ++c) {
            if (c > 0) ImGui::SameLine();
            ImGui::BeginChild(c == 0 ? "first column" : "second column", ImVec2(column_width, avail.y), false);
            draw_column(c, &changed, &load_env);
            ImGui::EndChild();
        }
        for (const ScriptedSet& s : config_.env_loads)
            if (s.frame == n) load_env = s.value;
        for (const ScriptedSet& s : config_.reference_loads)
            if (s.frame == n) {
                shown_references_ = scene::parse_look_dev_references(s.value, "--load-references");  // checked before the window opened
                references_ticked_ = true;
            }
        if (!load_env.empty() || references_ticked_) start_next_worker(load_env.empty() ? env_ : load_env, shown_references_);
        references_ticked_ = false;
        ImGui::End();
        return changed;
    }

    // The sections of one column, each open one's body in a scroll area of its own: the column's
    // height is shared among them (share_heights), so that they are all in view together.
    void draw_column(int column, bool* changed, std::string* load_env) {
        std::vector<size_t> in_column;
        for (size_t i = 0; i < sections_.size(); ++i)
            if (layout_.columns == 1 || sections_[i].column_of_two == column) in_column.push_back(i);
        std::vector<float> wanted;
        for (size_t i : in_column)
            if (sections_[i].open) wanted.push_back(sections_[i].wanted);
        const ImGuiStyle& style = ImGui::GetStyle();
        const float headers = float(in_column.size()) * ImGui::GetFrameHeightWithSpacing();
        const float available = ImGui::GetContentRegionAvail().y - headers - float(wanted.size()) * style.ItemSpacing.y;
        const std::vector<float> heights = share_heights(wanted, available, kMinSectionHeight);
        size_t k = 0;
        for (size_t i : in_column) {
            PanelSection& s = sections_[i];
            const bool was_open = s.open;
            ImGui::SetNextItemOpen(s.open, ImGuiCond_Always);
            s.open = ImGui::CollapsingHeader(s.name);
            // A section opened by this click has no share yet: the least, until the next frame.
            const float height = was_open ? heights[k++] : kMinSectionHeight;
            if (!s.open) continue;
            ImGui::BeginChild(s.name, ImVec2(0.0f, height), true);
            draw_section(SectionId(i), changed, load_env);
            s.wanted = ImGui::GetCursorPosY() + style.WindowPadding.y;  // the content's height, whatever the scroll
            ImGui::EndChild();
            const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
            s.rect = Rect{lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
        }
    }

    void draw_section(SectionId id, bool* changed, std::string* load_env) {
        switch (id) {
        case kMaterial:
            if (material_panel(&ui_.preset.material, ui_.reference.material)) {
                material_edited();
                *changed = true;
            }
            break;
        case kChecks: checks_.draw(); break;
        case kLobe: lobes_.draw(); break;
        case kEnvironment: environment_panel(&ui_, changed, &retone_, load_env, &shown_references_, &references_ticked_); break;
        case kPresets:
            if (preset_panel(&ui_)) {
                material_edited();
                *changed = true;
            }
            break;
        case kInspector: inspector_panel(config_, scene_, ui_, frame_, *worker_, picked_x_, picked_y_); break;
        case kHelp: help_panel(); break;
        case kSectionCount: break;
        }
    }

    // A headless run ends once the image shows the last state with enough samples (the screenshot,
    // the summary and the inspected pixels are written then), or fails when it has not within
    // kScriptTimeoutSeconds. Returns whether it ended.
    bool script_ended(int n, Clock::time_point now, int fb_width, int fb_height) {
        const bool current = frame_.generation >= submitted_ && frame_.scale == 1 && frame_.samples_per_pixel >= config_.min_samples &&
                             resize_pending_[0] == 0 && view_shown_ && !retone_ &&
                             (config_.save_exr.empty() || frame_has_layers(frame_, config_.save_layers)) &&
                             (!worker_b_ || (frame_b_.scale == 1 && frame_b_.samples_per_pixel >= config_.min_samples)) && !next_worker_;
        if (script_end_ == Clock::time_point{}) script_end_ = now;
        if (current || !worker_->error().empty() || worker_->status() == "no renderer") {
            if (!config_.screenshot.empty()) write_screenshot(config_.screenshot, fb_width, fb_height);
            if (!config_.save_exr.empty() && current) {
                save_frame_exr(config_.save_exr, frame_, config_.save_layers, ui_.tone_map, ui_.display_exposure);
                std::printf("wrote %s\n", config_.save_exr.c_str());
            }
            glfwSwapBuffers(window_.get());
            std::printf("view: %d frames, %d spp, %.3g samples/s on %s\n", n + 1, frame_.samples_per_pixel, frame_.samples_per_second,
                        worker_->device_description().c_str());
            if (!ui_.message.empty()) std::printf("view: message: %s\n", ui_.message.c_str());
            for (const std::array<int, 2>& px : config_.inspect) {
                std::string joined;
                for (const std::string& l : inspect_pixel(config_, scene_, ui_, frame_, *worker_, px[0], px[1])) joined += (joined.empty() ? "" : "; ") + l;
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
        if (config_.print_layout)
            for (const PanelSection& s : sections_)
                if (s.open) std::printf("section %s: %.0f,%.0f %.0fx%.0f\n", s.name, s.rect.x, s.rect.y, s.rect.w, s.rect.h);
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
    scene::Scene scene_ = config_.scene, next_scene_;  // what worker_ and next_worker_ render
    scene::LookDevReferences references_ = config_.references, next_references_;
    scene::LookDevReferences shown_references_ = config_.references;  // the panel's boxes
    bool references_ticked_ = false;
    std::string env_, next_env_;  // the map loaded last (empty: the one the viewer opened with)
    std::unique_ptr<RenderWorker> worker_;
    std::unique_ptr<RenderWorker> next_worker_, worker_b_;  // a new map being loaded; B of the split view
    RenderFrame frame_, frame_b_;
    uint64_t submitted_ = 1;  // the worker's first generation is the initial state
    std::vector<std::pair<uint64_t, Clock::time_point>> waiting_;  // scripted changes not yet on screen
    std::vector<std::pair<uint64_t, Clock::time_point>> waiting_denoised_;  // ... not yet on screen denoised
    Clock::time_point last_ = Clock::now(), script_end_{};
    bool retone_ = false;
    ViewMode view_mode_ = ViewMode::image;  // the view menu's choice (A's image; B shows its image)
    float error_threshold_ = config_.relative_error_threshold;
    bool view_shown_ = true;                // the texture shows view_mode_, not the image in its stead
    char exr_path_[512] = "view.exr";
    char exr_layers_[128] = "albedo,normal,depth,slot,variance,samples";
    std::optional<std::pair<std::string, render::AovSelection>> pending_exr_;  // "save EXR" pressed, waiting for its layers
    int picked_x_ = -1, picked_y_ = -1;  // of the render, as it is now
    std::vector<PanelSection> sections_;
    DisplaySizing sizing_ = config_.sizing;  // the panel can change it
    WindowLayout layout_;
    std::string layout_printed_;
    std::array<int, 2> resize_pending_{0, 0};  // a scripted window size not seen yet
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
    if (!config.export_material.empty()) {
        for (const std::string& n : export_material_file(ui.preset, config.export_material)) std::fprintf(stderr, "dtoadq: note: %s\n", n.c_str());
        std::printf("exported the material to %s\n", config.export_material.c_str());
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
