/* Packet kernels: the marches of eight rays per work-item on the vector lanes (sdf/march_lanes.h
 * with SDF_LANES = 8, which the host defines when it builds this program; the scene's field comes
 * in its packet form, scene/compile.cpp). Work-item g marches pixels 8 g .. 8 g + 7; the path
 * tracer's wavefront (kernels/path_tracer_wavefront.h) takes the results from `marches`. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "kernels/camera.h"
#include "kernels/ray_march.h"
#include "kernels/render_settings.h"
#include "kernels/rng.h"
#include "sdf/march_lanes.h"

SS_FN void store_marches(MarchLanes m, int first, int pixels, __global RayMarch* marches) {
    float t[8];
    int status[8], steps[8];
    vstore8(m.t, 0, t);
    vstore8(m.status, 0, status);
    vstore8(m.steps, 0, steps);
    for (int lane = 0; lane < 8 && first + lane < pixels; ++lane) {
        marches[first + lane].t = t[lane];
        marches[first + lane].status = status[lane];
        marches[first + lane].steps = steps[lane];
    }
}

/* The camera rays of sample settings.first_sample, drawn as the path tracer draws them
 * (camera_pixel_ray); a lane past the image marches its packet's first pixel again. */
__kernel void march_camera_rays(RenderKernelSettings settings, Camera camera, __global RayMarch* marches) {
    int first = 8 * (int)get_global_id(0);
    int pixels = camera.width * camera.height;
    if (first >= pixels) return;
    float o[3][8], v[3][8];
    for (int lane = 0; lane < 8; ++lane) {
        int pixel = first + lane < pixels ? first + lane : first;
        Rng rng = rng_make((uint)pixel, (uint)settings.first_sample, settings.seed_lo, settings.seed_hi);
        float3 origin, direction;
        camera_pixel_ray(&camera, pixel, &rng, &origin, &direction);
        o[0][lane] = origin.x, o[1][lane] = origin.y, o[2][lane] = origin.z;
        v[0][lane] = direction.x, v[1][lane] = direction.y, v[2][lane] = direction.z;
    }
    uint evaluations = 0u; /* counted only by a one-lane measurement build */
    MarchSettings s = render_march_settings(&settings);
    MarchLanes m = march_lanes(vload8(0, o[0]), vload8(0, o[1]), vload8(0, o[2]), vload8(0, v[0]), vload8(0, v[1]), vload8(0, v[2]), 0.0f,
                               s.max_distance, s, &evaluations);
    store_marches(m, first, pixels, marches);
}

/* The rays of `rays` (kernels/ray_march.h; `stride`: a multiple of 8 at least `pixels`). */
__kernel void march_rays(RenderKernelSettings settings, int pixels, int stride, __global const float* rays, __global RayMarch* marches) {
    int g = (int)get_global_id(0);
    if (8 * g >= pixels) return;
    uint evaluations = 0u;
    MarchLanes m = march_lanes(vload8(g, rays), vload8(g, rays + stride), vload8(g, rays + 2 * stride), vload8(g, rays + 3 * stride),
                               vload8(g, rays + 4 * stride), vload8(g, rays + 5 * stride), 0.0f, vload8(g, rays + 6 * stride),
                               render_march_settings(&settings), &evaluations);
    store_marches(m, 8 * g, pixels, marches);
}
