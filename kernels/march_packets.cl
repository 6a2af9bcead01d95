/* Packet kernels: marches on eight vector lanes per work-item (sdf/march_lanes.h with
 * SDF_LANES = 8, which the host defines when it builds this program; the scene's field comes in its
 * packet form, scene/compile.cpp). The path tracer's wavefront (kernels/path_tracer_wavefront.h)
 * takes the results from `marches`. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "kernels/ray_march.h"
#include "kernels/render_settings.h"
#include "sdf/march_lanes.h"

/* free lanes before a packet starts new rays (while the granule has rays left): half of them */
#define MARCH_REFILL_LANES 4

/* The lanes of a mask as the bits of a uint (bit l: lane l), and the lowest of them: the loops
 * below visit only the lanes they concern, in increasing order, instead of testing each of the
 * eight on a branch that the lanes' random finishing makes unpredictable. */
uint lane_bits(int8 mask) { return (uint)SDF_SUM(mask & (int8)(1, 2, 4, 8, 16, 32, 64, 128)); }
int lowest_lane(uint bits) { return 31 - (int)clz(bits & (0u - bits)); }

/* The rays of `rays` and `shadow_rays` (kernels/ray_march.h; `stride`: a multiple of 8 at least
 * `pixels`), into `marches` and `shadow_marches`, in one launch: work-items 0 .. granules - 1 take
 * the rays, granules .. 2 granules - 1 the shadow rays (granules: `pixels` in granules of
 * MARCH_RAYS_PER_ITEM), and the host launches only the half that has rays when the other has none.
 * A launch costs some fifty microseconds on a CPU, a tenth of a step of a simple scene. Work-item g
 * of its half marches rays MARCH_RAYS_PER_ITEM g ... up to `pixels` on eight lanes: a lane whose march is done
 * stores it and takes the next ray, skipping those that are none (a path that has ended), so the
 * lanes stay busy however long each ray's march and however few rays are left. A lane waits for
 * company until half the lanes are free: starting a ray costs a few dozen scalar operations. */
__kernel void march_rays(RenderKernelSettings settings, int pixels, int stride, __global const float* path_rays, __global RayMarch* path_marches,
                         __global const float* shadow_rays, __global RayMarch* shadow_marches) {
    const int granules = (pixels + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM;
    const int item = (int)get_global_id(0);
    const bool shadow = item >= granules;
    __global const float* rays = shadow ? shadow_rays : path_rays;
    __global RayMarch* marches = shadow ? shadow_marches : path_marches;
    const int first = (shadow ? item - granules : item) * MARCH_RAYS_PER_ITEM;
    const int end = min(first + MARCH_RAYS_PER_ITEM, pixels);
    const MarchSettings s = render_march_settings(&settings);
    uint evaluations = 0u;
    float field[RAY_FIELDS][8]; /* each lane's ray: origin, direction, max distance */
    int lane_ray[8];            /* the ray each lane marches; -1: none */
    for (int lane = 0; lane < 8; ++lane) {
        lane_ray[lane] = -1;
        for (int f = 0; f < RAY_FIELDS; ++f) field[f][lane] = NO_RAY;
    }
    float8 ox = 0.0f, oy = 0.0f, oz = 0.0f, vx = 0.0f, vy = 0.0f, vz = 1.0f, max_distance = NO_RAY;
    MarchLanesState st = march_lanes_start(ox, oy, oz, vx, vy, vz, (float8)0.0f, max_distance, s);
    int next = first;
    int8 holding = 0; /* the lanes that have a ray, marched or marching */
    for (;;) {
        const int8 free = !st.running;
        /* free lanes: their marches to store, new rays to start */
        if (next < end ? -SDF_SUM(free) >= MARCH_REFILL_LANES : any(holding && free)) {
            int started[8], status[8], steps[8];
            float t[8];
            vstore8(st.m.t, 0, t);
            vstore8(st.m.status, 0, status);
            vstore8(st.m.steps, 0, steps);
            vstore8((int8)0, 0, started);
            for (uint done = lane_bits(free && holding); done != 0u; done &= done - 1u) {
                const int lane = lowest_lane(done);
                marches[lane_ray[lane]].t = t[lane];
                marches[lane_ray[lane]].status = status[lane];
                marches[lane_ray[lane]].steps = steps[lane];
                lane_ray[lane] = -1;
            }
            if (!any(st.running) && next + 8 <= end && !any(0.0f > vload8(0, rays + 6 * stride + next))) {
                /* eight rays in a row, as a camera's: a packet of neighbouring pixels, loaded whole */
                for (int f = 0; f < RAY_FIELDS; ++f) vstore8(vload8(0, rays + f * stride + next), 0, field[f]);
                for (int lane = 0; lane < 8; ++lane) {
                    lane_ray[lane] = next + lane;
                    started[lane] = -1;
                }
                next += 8;
            } else {
                for (uint idle = lane_bits(free); idle != 0u; idle &= idle - 1u) {
                    const int lane = lowest_lane(idle);
                    while (next < end && 0.0f > rays[6 * stride + next]) ++next; /* no ray: its march is never read */
                    if (next >= end) break;
                    for (int f = 0; f < RAY_FIELDS; ++f) field[f][lane] = rays[f * stride + next];
                    lane_ray[lane] = next++;
                    started[lane] = -1;
                }
            }
            holding = vload8(0, lane_ray) >= 0;
            const int8 start = vload8(0, started);
            if (any(start)) {
                ox = vload8(0, field[0]);
                oy = vload8(0, field[1]);
                oz = vload8(0, field[2]);
                vx = vload8(0, field[3]);
                vy = vload8(0, field[4]);
                vz = vload8(0, field[5]);
                max_distance = vload8(0, field[6]);
                st = march_lanes_restart(st, start, ox, oy, oz, vx, vy, vz, (float8)0.0f, max_distance, s);
            }
        }
        if (!any(st.running)) {
            /* a new ray may be done before its first step (it starts past its exit from the
             * surface box): its march is stored at the top like any other */
            if (next >= end && !any(holding)) break;
            continue;
        }
        march_lanes_advance(&st, ox, oy, oz, vx, vy, vz, max_distance, s, &evaluations);
    }
}
