/* A compiled scene's rays, for the test that the OpenCL build of the exact intersections and of
 * the rule that combines them with the march (sdf/exact/trace.h) agrees with the host build. Rays
 * are 6 floats each (origin, unit direction). */

/* No fused multiply-add: the host build rounds every product. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"
#include "sdf/exact/trace.h"

__kernel void scene_ray_probe(int count, float max_distance, __global const float* rays, __global float* exact_t, __global float* hit_t,
                              __global int* status) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    float3 o = (float3)(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2]);
    float3 v = (float3)(rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5]);
    MarchSettings s = march_settings_default(SCENE_LIPSCHITZ);
    s.max_distance = max_distance;
    exact_t[i] = scene_exact_hit(o, v, max_distance);
    MarchResult r = march_scene_ray(o, v, s);
    hit_t[i] = r.t;
    status[i] = r.status;
}
