#include "viewer/pixel_probe.hpp"

#include "scene/interpreter.hpp"

namespace lab::viewer {

// The march and the normals call the scene's distance field as free functions: here the host
// interpreter's, for the scene being probed.
namespace probe_code {

using namespace ::kernel;
thread_local const scene::Scene* current_scene = nullptr;

inline float scene_distance(float3 p) { return scene::scene_distance(*current_scene, p); }
inline float scene_distance_material(float3 p, int* material) { return scene::scene_distance_material(*current_scene, p, material); }
inline int scene_analytic_normal(float3 p, float3* n) { return scene::scene_analytic_normal(*current_scene, p, n); }

#include "sdf/march.h"
#include "sdf/normals.h"
#include "kernels/path.h"

}  // namespace probe_code

PixelProbe probe_pixel(const scene::Scene& scene, const kernel::RenderKernelSettings& k, const kernel::Camera& camera, int x, int y) {
    using namespace probe_code;
    current_scene = &scene;
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
