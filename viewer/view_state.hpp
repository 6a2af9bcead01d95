// What the interface asks the renderer to show: the edits that restart accumulation without a new
// renderer (render/renderer.hpp). The interface owns one, changes it, and hands copies to the
// render worker; equal states need no restart.
#pragma once

#include <vector>

#include "brdf/brdf.hpp"
#include "scene/scene.hpp"

namespace lab::viewer {

struct ViewState {
    std::vector<brdf::Material> materials;  // one per slot of the compiled scene
    scene::Camera camera;
    float env_rotation_degrees = 0.0f;      // absolute, as ibl::EnvironmentOptions
    float env_exposure_stops = 0.0f;
    bool show_background = true;            // B: off shows the backdrop at opacity 0
    float background_opacity = 1.0f;        // what camera rays see of the map (kernels/background.h)
    float background_blur_degrees = 0.0f;
    int width = 0, height = 0;  // the render's full size (the window's render area); 0: the renderer's own
};

}  // namespace lab::viewer
