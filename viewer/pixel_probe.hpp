// The pixel inspector's geometry: the camera ray through a pixel's centre traced on the host with
// the render core's own single-source code (kernels/camera.h, sdf/march.h, sdf/normals.h through
// the scene interpreter: render/host_kernels.hpp), giving what the film does not hold: depth,
// normal and material slot. Radiance and sample count come from the film.
#pragma once

#include "kernels/host.hpp"
#include "scene/scene.hpp"

namespace lab::viewer {

struct PixelProbe {
    bool hit = false;
    float depth = 0.0f;        // distance along the camera ray
    scene::Vec3 position{0.0f}, normal{0.0f};
    int material = -1;         // slot
};

// x, y in pixels from the top-left corner. `scene` as the renderer has it (options applied).
PixelProbe probe_pixel(const scene::Scene& scene, const kernel::RenderKernelSettings& settings, const kernel::Camera& camera, int x, int y);

}  // namespace lab::viewer
