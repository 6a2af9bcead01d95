/* Packet kernels: the marches of eight rays per work-item on the vector lanes (sdf/march_lanes.h
 * with SDF_LANES = 8, which the host defines when it builds this program; the scene's field comes
 * in its packet form, scene/compile.cpp). Work-item g marches pixels 8 g .. 8 g + 7; the path
 * tracer's wavefront (kernels/path_tracer_wavefront.h) takes the results from `marches`. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "kernels/ray_march.h"
#include "kernels/render_settings.h"
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
