#include "viewer/pixel_probe.hpp"

#include "scene/field_for_kernel_headers.hpp"

namespace lab::viewer {

// The march and the normals call the scene's distance field as free functions: here the host
// interpreter's, for the scene being probed.
namespace probe_code {

using namespace ::kernel;
using namespace scene::field_for_kernel_headers;

#include "sdf/march.h"
#include "sdf/normals.h"
#include "kernels/path.h"

}  // namespace probe_code

PixelProbe probe_pixel(const scene::Scene& scene, const kernel::RenderKernelSettings& k, const kernel::Camera& camera, int x, int y) {
    using namespace probe_code;
    scene::field_for_kernel_headers::current_scene = &scene;
    float3 origin, direction;
    camera_generate_ray(&camera, float(x) + 0.5f, float(y) + 0.5f, make_float2(0.5f, 0.5f), &origin, &direction);
    MarchResult r = march(origin, direction, 0.0f, render_march_settings(&k));
    PixelProbe p;
    if (r.status != MARCH_HIT) return p;
    p.hit = true;
    p.depth = r.t;
    p.position = origin + direction * r.t;
    p.normal = scene_normal(p.position, k.normal_step, k.normal_method);
    scene_distance_material(p.position, &p.material);
    return p;
}

}  // namespace lab::viewer
