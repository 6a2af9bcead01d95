#include "viewer/pixel_probe.hpp"

#include "render/host_kernels.hpp"

namespace lab::viewer {

PixelProbe probe_pixel(const scene::Scene& scene, const kernel::RenderKernelSettings& settings, const kernel::Camera& camera, int x, int y) {
    using namespace render::host_kernels;
    const render::HostSceneScope scene_scope(scene);
    float3 origin, direction;
    camera_generate_ray(&camera, float(x) + 0.5f, float(y) + 0.5f, make_float2(0.5f, 0.5f), &origin, &direction);
    MarchResult r = march_scene_ray(origin, direction, render_march_settings(&settings));
    PixelProbe p;
    if (r.status != MARCH_HIT) return p;
    p.hit = true;
    p.depth = r.t;
    p.position = origin + direction * r.t;
    p.normal = surface_normal(&settings, p.position, &p.material);
    return p;
}

}  // namespace lab::viewer
