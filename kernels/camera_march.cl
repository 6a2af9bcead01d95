/* The camera rays' marches of one sample of every pixel of a launch, eight rays per work-item on
 * the vector lanes (sdf/march_lanes.h with SDF_LANES = 8, which the host defines when it builds this
 * kernel; the scene's field comes in its packet form, scene/compile.cpp). The path tracer then takes
 * each pixel's march from `marches` (kernels/path.h, trace_camera_ray) instead of marching its
 * camera ray one lane at a time. Work-item g holds pixels 8 g .. 8 g + 7; a pixel past the image
 * marches its row's first pixel again and writes nothing. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "kernels/camera.h"
#include "kernels/camera_march.h"
#include "kernels/render_settings.h"
#include "kernels/rng.h"
#include "sdf/march_lanes.h"

__kernel void camera_march(RenderKernelSettings settings, Camera camera, __global CameraMarch* marches) {
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
    uint evaluations = 0u; /* counted only by a scalar measurement build */
    MarchSettings s = render_march_settings(&settings);
    MarchLanes m = march_lanes(vload8(0, o[0]), vload8(0, o[1]), vload8(0, o[2]), vload8(0, v[0]), vload8(0, v[1]), vload8(0, v[2]), 0.0f,
                               s.max_distance, s, &evaluations);
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
