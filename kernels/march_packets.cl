/* Packet kernels: marches on eight vector lanes per work-item (sdf/march_lanes.h with
 * SDF_LANES = 8, which the host defines when it builds this program; the scene's field comes in its
 * packet form, scene/generated_source.cpp). The path tracer's wavefront (kernels/path_tracer_wavefront.h)
 * takes the results from `marches`. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "kernels/camera.h"
#include "kernels/ray_march.h"
#include "kernels/render_settings.h"
#include "sdf/exact/with_march.h"
#include "sdf/march_lanes.h"

/* free lanes before a packet starts new rays (while the granule has rays left): half of them */
#define MARCH_REFILL_LANES 4

/* The lanes of a mask as the bits of a uint (bit l: lane l), and the lowest of them: the loops
 * below visit only the lanes they concern, in increasing order, instead of testing each of the
 * eight on a branch that the lanes' random finishing makes unpredictable. */
uint lane_bits(int8 mask) { return (uint)SDF_SUM(mask & (int8)(1, 2, 4, 8, 16, 32, 64, 128)); }
int lowest_lane(uint bits) { return 31 - (int)clz(bits & (0u - bits)); }

/* The rays first .. end - 1 of `rays` (kernels/ray_march.h) into `marches`, on eight lanes: a lane
 * whose march is done stores it and takes the next ray, skipping those that are none (a path that
 * has ended), so the lanes stay busy however long each ray's march and however few rays are left.
 * A lane waits for company until half the lanes are free: starting a ray costs a few dozen scalar
 * operations. A ray's exact hits are found when it starts, on the lanes (the generated
 * scene_exact_hit_lanes, to the bit the scalar scene_exact_hit): its march stops there, and the exact
 * hit is taken when the march finds nothing nearer (sdf/exact/with_march.h, as trace_ray in
 * kernels/path.h). */
SS_FN SS_INLINE_ALWAYS void march_granule(MarchSettings march_settings, int first, int end, int stride, __global const float* rays, __global RayMarch* marches) {
    if (scene_march_objects() == 0) {
        /* nothing to march: a ray's exact hit is all there is, without the lanes' bookkeeping; what
         * a march that is done before its first step and its exact hit give (march_scene_ray), eight
         * rays at a time (the granule starts at a multiple of 8 and the stride is a multiple of 8, so
         * a packet's loads stay in the buffer; the lanes past `end` are not stored) */
        for (int packet = first; packet < end; packet += 8) {
            const float8 max_distance = vload8(0, rays + 6 * stride + packet);
            const int8 ray = (int8)(0, 1, 2, 3, 4, 5, 6, 7) < (int8)(end - packet) && !(0.0f > max_distance);
            if (!any(ray)) continue;
            float8 t = 0.0f;
            int8 status = MARCH_MISS;
            exact_or_march_lanes(scene_exact_hit_lanes(vload8(0, rays + packet), vload8(0, rays + stride + packet), vload8(0, rays + 2 * stride + packet),
                                                       vload8(0, rays + 3 * stride + packet), vload8(0, rays + 4 * stride + packet),
                                                       vload8(0, rays + 5 * stride + packet), max_distance),
                                 max_distance, &t, &status);
            float lane_t[8];
            int lane_status[8];
            vstore8(t, 0, lane_t);
            vstore8(status, 0, lane_status);
            for (uint stored = lane_bits(ray); stored != 0u; stored &= stored - 1u) {
                const int lane = lowest_lane(stored);
                marches[packet + lane].t = lane_t[lane];
                marches[packet + lane].status = lane_status[lane];
                marches[packet + lane].steps = 0;
            }
        }
        return;
    }
    uint evaluations = 0u;
    float field[RAY_FIELDS][8]; /* each lane's ray: origin, direction, max distance */
    int lane_ray[8];            /* the ray each lane marches; -1: none */
    for (int lane = 0; lane < 8; ++lane) {
        lane_ray[lane] = -1;
        for (int f = 0; f < RAY_FIELDS; ++f) field[f][lane] = NO_RAY;
    }
    float8 ox = 0.0f, oy = 0.0f, oz = 0.0f, vx = 0.0f, vy = 0.0f, vz = 1.0f, max_distance = NO_RAY;
    float8 exact_t = INFINITY; /* each lane's nearest exact hit, none yet */
    float8 ray_max = NO_RAY;   /* each lane's max distance, before the march's is cut at that hit */
    MarchLanesState st = march_lanes_start(ox, oy, oz, vx, vy, vz, (float8)0.0f, max_distance, (int8)0, march_settings);
    int next = first;
    int8 holding = 0; /* the lanes that have a ray, marched or marching */
    for (;;) {
        const int8 free = !st.running;
        /* free lanes: their marches to store, new rays to start */
        if (next < end ? -SDF_SUM(free) >= MARCH_REFILL_LANES : any(holding && free)) {
            int started[8], status[8], steps[8];
            float t[8];
            float8 ray_t = st.m.t;
            int8 ray_status = st.m.status;
            exact_or_march_lanes(exact_t, ray_max, &ray_t, &ray_status);
            vstore8(ray_t, 0, t);
            vstore8(ray_status, 0, status);
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
                /* the new rays' exact hits: one lane-form call for every lane (at least four
                 * start while rays are left), kept in those that start */
                ox = select(ox, vload8(0, field[0]), start);
                oy = select(oy, vload8(0, field[1]), start);
                oz = select(oz, vload8(0, field[2]), start);
                vx = select(vx, vload8(0, field[3]), start);
                vy = select(vy, vload8(0, field[4]), start);
                vz = select(vz, vload8(0, field[5]), start);
                ray_max = select(ray_max, vload8(0, field[6]), start);
                exact_t = select(exact_t, scene_exact_hit_lanes(ox, oy, oz, vx, vy, vz, ray_max), start);
                max_distance = select(max_distance, exact_march_limit_lanes(ray_max, exact_t, scene_march_objects()), start);
                st = march_lanes_restart(st, start, ox, oy, oz, vx, vy, vz, (float8)0.0f, max_distance, exact_t <= ray_max, march_settings);
            }
        }
        if (!any(st.running)) {
            /* a new ray may be done before its first step (it starts past its exit from the
             * surface box): its march is stored at the top like any other */
            if (next >= end && !any(holding)) break;
            continue;
        }
        march_lanes_advance(&st, ox, oy, oz, vx, vy, vz, max_distance, march_settings, &evaluations);
    }
}

/* The rays of `rays` and `shadow_rays` (kernels/ray_march.h; `stride`: a multiple of 8 at least
 * `pixels`), into `marches` and `shadow_marches`, in one launch: work-items 0 .. granules - 1 take
 * the rays, granules .. 2 granules - 1 the shadow rays (granules: `pixels` in granules of
 * MARCH_RAYS_PER_ITEM), and the host launches only the half that has rays when the other has none.
 * A launch costs some fifty microseconds on a CPU, a tenth of a step of a simple scene. Work-item g
 * of its half marches rays MARCH_RAYS_PER_ITEM g ... up to `pixels` (march_granule). A launch's
 * first work-item is `first_item`, not a global offset (render/opencl_launch.hpp says why): the
 * shadow half alone starts at `granules`. */
__kernel void march_rays(RenderKernelSettings settings, int pixels, int stride, __global const float* path_rays, __global RayMarch* path_marches,
                         __global const float* shadow_rays, __global RayMarch* shadow_marches, int first_item) {
    const int granules = (pixels + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM;
    const int item = first_item + (int)get_global_id(0);
    const bool shadow = item >= granules;
    const int first = (shadow ? item - granules : item) * MARCH_RAYS_PER_ITEM;
    march_granule(render_march_settings(&settings), first, min(first + MARCH_RAYS_PER_ITEM, pixels), stride, shadow ? shadow_rays : path_rays,
                  shadow ? shadow_marches : path_marches);
}

/* The wavefront's camera rays of a pinhole camera (kernels/path_tracer_wavefront.h), begun on the
 * lanes and marched: work-item g (from `first_item`, render/opencl_launch.hpp) takes the `paths`
 * granule g holds, eight at a time, and leaves
 * each path's camera ray in `rays` and its generator after the ray's four numbers in `camera_rngs`
 * (four arrays of `stride` words), as path_tracer_camera_step computes them one path at a time, to
 * the bit; then it marches them (march_granule). One launch instead of a camera step and a march,
 * and the camera's Philox, divisions and square root eight paths to an instruction: a camera
 * step of one path per work-item costs a seventh of the sphere's time. */
__kernel void march_camera_rays(RenderKernelSettings settings, Camera camera, int paths, int stride, __global float* rays,
                                __global uint* camera_rngs, __global RayMarch* marches, int first_item) {
    const int first = (first_item + (int)get_global_id(0)) * MARCH_RAYS_PER_ITEM;
    if (first >= paths) return;
    const int end = min(first + MARCH_RAYS_PER_ITEM, paths);
    const int pixels = camera.width * camera.height;
    const MarchSettings march_settings = render_march_settings(&settings);
    /* the stride is a multiple of 8 (kernels/ray_march.h): the lanes of a last packet past `end`
     * store no ray, as the padding holds */
    for (int packet = first; packet < end; packet += 8) {
        const int8 path = packet + (int8)(0, 1, 2, 3, 4, 5, 6, 7);
        const int8 slot = path / pixels, pixel = path - slot * pixels;
        RngLanes rng = rng_make_lanes(convert_uint8(pixel), convert_uint8(settings.first_sample + slot), settings.seed_lo, settings.seed_hi);
        float8 dx, dy, dz;
        camera_pinhole_pixel_rays(&camera, pixel, &rng, &dx, &dy, &dz);
        vstore8((float8)camera.position[0], 0, rays + packet);
        vstore8((float8)camera.position[1], 0, rays + stride + packet);
        vstore8((float8)camera.position[2], 0, rays + 2 * stride + packet);
        vstore8(dx, 0, rays + 3 * stride + packet);
        vstore8(dy, 0, rays + 4 * stride + packet);
        vstore8(dz, 0, rays + 5 * stride + packet);
        vstore8(select((float8)march_settings.max_distance, (float8)NO_RAY, path >= end), 0, rays + 6 * stride + packet);
        vstore8(rng.s0, 0, camera_rngs + packet);
        vstore8(rng.s1, 0, camera_rngs + stride + packet);
        vstore8(rng.s2, 0, camera_rngs + 2 * stride + packet);
        vstore8(rng.s3, 0, camera_rngs + 3 * stride + packet);
    }
    march_granule(march_settings, first, end, stride, rays, marches);
}
