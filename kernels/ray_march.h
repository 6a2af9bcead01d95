/* What the path tracer's wavefront (kernels/path_tracer_wavefront.h) and the packet kernels
 * (kernels/march_packets.cl) hand each other, one entry per pixel:
 *  - rays: seven arrays of `stride` floats (origin x, y, z, direction x, y, z, max distance), so that
 *    a packet kernel loads eight pixels' component at once; a max distance < 0 marks no ray;
 *  - marches: what each ray's march found (sdf/march_lanes.h's MarchLanes, one lane); nothing is
 *    written for no ray;
 *  - camera_rngs: four arrays of `stride` words, a path's generator (kernels/rng.h, Rng s0 .. s3)
 *    after its camera ray drew its four numbers, left by the camera rays for the first step. */
#ifndef KERNELS_RAY_MARCH_H
#define KERNELS_RAY_MARCH_H

#include "single_source/vocabulary.h"

#define RAY_FIELDS 7
#define NO_RAY -1.0f /* a max distance that marches nothing: the lane is done before it starts */
/* rays per work-item of a packet kernel: a launch's pixel range is made of whole granules of 64
 * (render/renderer.hpp, kLaunchGranularity) */
#define MARCH_RAYS_PER_ITEM 64

typedef struct RayMarch {
    float t;
    int status;
    int steps;
} RayMarch;

SS_FN void store_ray(GLOBAL_MEM float* rays, int stride, int pixel, float3 origin, float3 direction, float max_distance) {
    rays[pixel] = origin.x;
    rays[stride + pixel] = origin.y;
    rays[2 * stride + pixel] = origin.z;
    rays[3 * stride + pixel] = direction.x;
    rays[4 * stride + pixel] = direction.y;
    rays[5 * stride + pixel] = direction.z;
    rays[6 * stride + pixel] = max_distance;
}

/* The origin and direction store_ray left for pixel `pixel`. */
SS_FN void load_ray(GLOBAL_MEM const float* rays, int stride, int pixel, float3* origin, float3* direction) {
    *origin = make_float3(rays[pixel], rays[stride + pixel], rays[2 * stride + pixel]);
    *direction = make_float3(rays[3 * stride + pixel], rays[4 * stride + pixel], rays[5 * stride + pixel]);
}

/* No ray for pixel `pixel`: its max distance alone, which is all that a packet kernel reads of a
 * ray before it knows that there is one. */
SS_FN void store_no_ray(GLOBAL_MEM float* rays, int stride, int pixel) { rays[6 * stride + pixel] = NO_RAY; }

#endif
