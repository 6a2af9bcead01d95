// What the viewer opens with: the renderer's factory, the scene and material, the window's size and
// display, and the headless automation's script (run_viewer, viewer/app.hpp).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "film/tone_map.hpp"
#include "scene/look_dev_references.hpp"
#include "scene/scene.hpp"
#include "render/aov_layers.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/script.hpp"
#include "viewer/view_state.hpp"
#include "viewer/window_layout.hpp"

namespace lab::viewer {

struct ViewerConfig {
    RenderWorker::RendererFactory make_renderer;
    // The factory of a renderer under another environment map (empty: the one the viewer opened
    // with) and with other look-dev references (the environment panel); its errors (a missing or bad
    // map) come from the worker that calls it.
    std::function<RenderWorker::RendererFactory(const std::string& env, const scene::LookDevReferences& references)> factory_for;
    ViewState initial;
    scene::Scene scene;                // as the renderer has it: for the pixel inspector's rays
    scene::Scene base_scene;           // the same without look-dev references
    scene::LookDevReferences references;  // those in `scene`
    int width = 256, height = 256;     // of the render as opened (and its aspect); the window adds the panel beside it
    int window_width = 0, window_height = 0;  // the window's first size; 0: the render's and the panel's
    DisplaySizing sizing = DisplaySizing::Render;  // what resizing the window changes
    long max_render_pixels = 512 * 512;  // under DisplaySizing::Render: larger areas show the render scaled up (docs/viewer.md: what it keeps)
    std::vector<std::string> open_sections;  // panel sections open from the start (besides Material and Checks); "all"
    int edited_slot = 0;               // the slot the material panel edits
    brdf::Preset preset;               // its material as loaded: what "reset" returns to
    brdf::Preset compare;              // B of the lobe panel's A/B overlay
    std::string title;
    int max_samples = 1 << 16;
    double chunk_seconds = 1.0 / 30.0; // the render worker's budget per chunk
    film::ToneMap tone_map = film::ToneMap::Aces;
    float display_exposure = 0.0f;
    bool denoise = true;               // the display denoised while it accumulates (viewer/display_denoiser.hpp)

    // Headless automation: with frames > 0 the viewer closes itself after that many frames and
    // once the image shows every scripted change.
    bool split = false;                // start in the A/B split view
    int frames = 0;
    int min_samples = 1;               // ... and the image has at least this many samples per pixel
    std::vector<ScriptedSet> sets;
    std::vector<ScriptedSet> moves;      // --move KEY=VALUE@FRAME: camera and environment changes (viewer/script.hpp)
    std::vector<ScriptedSet> env_loads;  // --load-env PATH@FRAME: as the environment panel's "load map" (key unused)
    std::vector<ScriptedSet> reference_loads;  // --load-references LIST@FRAME: as the environment panel's checkboxes (key unused)
    std::vector<ScriptedSet> resizes;    // --resize WxH@FRAME: the window resized, as a window manager does (key unused)
    std::vector<ScriptedSet> view_modes; // --view-mode NAME@FRAME: the view menu's choice (key unused; checked by parse_view_mode)
    float relative_error_threshold = 0.05f;  // the relative-error view's, until the menu changes it
    std::string screenshot;            // PNG of the whole window at the last frame
    std::string save_exr;              // --save-exr: the frame's EXR at the last frame, with the layers of save_layers
    render::AovSelection save_layers;
    std::string save_preset;           // written on exit
    std::string export_scene, export_name;  // written on exit
    std::string export_material;       // a .mtlx, .gltf, .xml (Mitsuba 3) or .pbrt file written on exit (viewer/material_export.hpp)
    std::vector<std::array<int, 2>> inspect;  // pixels whose inspector lines are printed at the end
    bool stats = false;                // print frame times, samples/s and change latency on exit
    bool print_layout = false;         // print each new layout of the window, and the open sections' places on exit
};

}  // namespace lab::viewer
