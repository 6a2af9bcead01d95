// The panels and mouse handling of the viewer's window beside the material, lobe and check panels:
// environment, presets, pixel inspector, help, and the mouse on the render (camera, environment,
// A/B divider, picking). Each draws into the current ImGui window and says what it changed.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "film/tone_map.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/view_state.hpp"
#include "viewer/viewer_config.hpp"
#include "viewer/window_layout.hpp"

namespace lab::viewer {

// Everything the interface edits, and what it last handed to the render worker.
struct UiState {
    ViewState view;
    brdf::Preset reference;  // what "reset" returns to: the preset as loaded
    brdf::Preset preset;  // the edited material (preset.material mirrors view.materials[slot])
    film::ToneMap tone_map = film::ToneMap::Aces;
    float display_exposure = 0.0f;
    char preset_path[512] = "material.json";
    char export_target[512] = "scene.json:material";
    char export_file[512] = "material.mtlx";  // .mtlx, .gltf, .xml (Mitsuba 3) or .pbrt
    char env_path[512] = "";
    bool split = false;       // A/B split view
    bool denoise = true;      // the display denoised (viewer/display_denoiser.hpp); the film never is
    float split_x = 0.5f;     // the divider, as a fraction of the width
    std::string message;  // the last error or confirmation, shown in the panel
};

// Environment: rotation, light exposure, background, tone map, display exposure; a map from
// envmaps/ or a path (*load_env gets it: the window swaps renderers once the new one is ready);
// the look-dev references (*references; *references_changed when a box was ticked, for a new
// renderer the same way).
void environment_panel(UiState* ui, bool* changed, bool* retone, std::string* load_env, scene::LookDevReferences* references,
                       bool* references_changed);
// Load (a bad file leaves everything as it was and says why), save, export to scene; returns
// whether a preset was loaded (it is then both ui->preset and ui->reference).
bool preset_panel(UiState* ui);
// Mouse over the render: orbit, pan, zoom, Ctrl+drag turns the environment, a drag near the A/B
// divider moves it, right-click picks a pixel (of the render_width x render_height render drawn in
// `image`). Returns whether the view changed.
bool mouse_on_render(UiState* ui, const Rect& image, int render_width, int render_height, int* picked_x, int* picked_y);
// The inspector's lines for pixel (x, y): film radiance and samples, then the probe's geometry.
// `scene` is the one the worker renders (with its look-dev references).
std::vector<std::string> inspect_pixel(const ViewerConfig& config, const scene::Scene& scene, const UiState& ui, const RenderFrame& frame,
                                       const RenderWorker& worker, int x, int y);
void inspector_panel(const ViewerConfig& config, const scene::Scene& scene, const UiState& ui, const RenderFrame& frame, const RenderWorker& worker,
                     int x, int y);
void help_panel();

}  // namespace lab::viewer
