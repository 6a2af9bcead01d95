/* A compiled scene's exact hits in their lane form (scene_exact_hit_lanes, what the packet kernels
 * call) beside the scalar form in the same program, for the test that they agree to the bit. Built
 * with SDF_LANES = 8. Rays: seven arrays of `stride` floats (origin, unit direction, t_max), `stride` a
 * multiple of 8; work-item g takes rays 8 g .. 8 g + 7. */

/* as the packet kernels: no fused multiply-add */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

__kernel void scene_exact_lanes_probe(int stride, __global const float* rays, __global float* lanes_t, __global float* scalar_t) {
    const int packet = 8 * (int)get_global_id(0);
    if (packet >= stride) return;
    vstore8(scene_exact_hit_lanes(vload8(0, rays + packet), vload8(0, rays + stride + packet), vload8(0, rays + 2 * stride + packet),
                                  vload8(0, rays + 3 * stride + packet), vload8(0, rays + 4 * stride + packet), vload8(0, rays + 5 * stride + packet),
                                  vload8(0, rays + 6 * stride + packet)),
            0, lanes_t + packet);
    for (int i = packet; i < packet + 8; ++i)
        scalar_t[i] = scene_exact_hit((float3)(rays[i], rays[stride + i], rays[2 * stride + i]),
                                      (float3)(rays[3 * stride + i], rays[4 * stride + i], rays[5 * stride + i]), rays[6 * stride + i]);
}
