/* The path tracer as a wavefront on OpenCL: the same paths as kernels/path_tracer.h's trace_path,
 * with every march taken out of the work-item, so that packet kernels (kernels/march_packets.cl)
 * march eight rays at a time on the vector lanes. A launch of one or more samples (WavefrontFilm,
 * below: one path per pixel and sample) runs, for every path:
 *
 *   iteration 0, the camera ray: march_camera_rays (kernels/march_packets.cl: a pinhole's rays
 *   drawn on the packets' lanes, then marched), or path_tracer_camera_step and march_rays (a thin
 *   lens);  then  path_tracer_step (iteration 1, 2, ...);  march_rays (its rays and shadow rays);  ...
 *
 * until a step leaves no ray to march. Iteration 0 leaves each path's camera ray in the ray buffer
 * and its generator (after the ray's four numbers) in camera_rngs; the first step begins the path
 * with them, a later one resolves the path's pending shadow ray with its march; then each takes
 * the march of its ray and scatters (path_scatter), leaving its next ray and shadow ray in the ray
 * buffers (kernels/ray_march.h) and its state in `states`. That is trace_path's order of operations, so a
 * wavefront sample gives the bits of the same sample traced in one work-item (the host's). A path
 * with nothing left to march adds its radiance to the film, as path_tracer_pixel does. Every
 * pixel's path is at the same step, so the rays of a packet (neighbouring pixels) stay alike.
 * OpenCL only. */
#ifndef KERNELS_PATH_TRACER_WAVEFRONT_H
#define KERNELS_PATH_TRACER_WAVEFRONT_H

#include "kernels/path_tracer.h"
#include "kernels/ray_march.h"

SS_FN MarchResult load_march(GLOBAL_MEM const RayMarch* marches, int path) {
    MarchResult r;
    r.t = marches[path].t;
    r.status = marches[path].status;
    r.steps = marches[path].steps;
    return r;
}

/* Pixels ahead whose environment texel a step prefetches: a step takes some hundred nanoseconds, a
 * line from memory about as long. The entry of the alias table that a light sample reads before its
 * texel is asked for twice as far ahead, so that it is in the cache when the texel's turn comes. */
#define WAVEFRONT_PREFETCH_AHEAD 4

/* Whether a path at depth `depth` whose generator is `rng` scatters at this step and draws its light
 * sample from the environment, with the two numbers that sample will use in *u: the step peeks at
 * them through a copy of the path's generator (path_scatter's u_light: xy the sample, w the choice
 * of light). A path that ends at an emitter draws nothing: a prefetch for it is wasted, not wrong. */
SS_FN bool peek_environment_sample(const RenderKernelSettings* settings, const RenderScene* scene, int depth, Rng rng, float2* u) {
    if (depth >= settings->max_depth || settings->light_sampling == LIGHT_SAMPLING_BSDF || settings->light_count <= 0) return false;
    float4 numbers = rng_next4(&rng);
    float pmf;
    int index = select_light(scene->light_cdf, settings->light_count, numbers.w, &pmf);
    if (!(pmf > 0.0f) || scene->lights[index].type != LIGHT_ENVIRONMENT) return false;
    *u = make_float2(numbers.x, numbers.y);
    return true;
}

/* The generator a camera ray left for its path's first step (camera_rngs: four arrays of `stride`
 * words, kernels/ray_march.h), and its store by the scalar camera step. */
SS_FN Rng load_camera_rng(GLOBAL_MEM const uint* camera_rngs, int stride, int path) {
    Rng r;
    r.s0 = camera_rngs[path];
    r.s1 = camera_rngs[stride + path];
    r.s2 = camera_rngs[2 * stride + path];
    r.s3 = camera_rngs[3 * stride + path];
    return r;
}

SS_FN void store_camera_rng(GLOBAL_MEM uint* camera_rngs, int stride, int path, Rng r) {
    camera_rngs[path] = r.s0;
    camera_rngs[stride + path] = r.s1;
    camera_rngs[2 * stride + path] = r.s2;
    camera_rngs[3 * stride + path] = r.s3;
}

/* Asks the cache for what path `path` reads from the environment at this step: a map
 * of megabytes, looked up in random directions, misses the caches nearly every time, and one
 * work-item's lookups are not overlapped.
 *  - Its ray escaped: the texel of its direction (environment_radiance_pdf, one cache line). A
 *    camera ray's filtered lookup is left out: neighbouring pixels read neighbouring texels.
 *  - Its ray hit a surface it scatters from, and the environment is the light it chooses: the texel
 *    its light sample draws (`texel`) or, from further ahead, the entry of the drawn row's alias
 *    table that names that texel (!texel). The rows' own table is small enough to stay cached, so
 *    neither peek waits for memory: each address is known without a load that misses.
 * Only with PoCL, whose compiler (clang) has the builtin and whose CPU wavefront builds this program
 * with WAVEFRONT_PREFETCH; nothing else changes, not a bit of the image. The path may belong to a
 * work-group that another thread is stepping: whatever state it reads, every index stays inside its
 * buffer (the numbers are in [0, 1), a direction's texel is clamped), and only a prefetch uses it. */
SS_FN SS_INLINE_ALWAYS void prefetch_step_environment(const RenderKernelSettings* settings, const RenderScene* scene, GLOBAL_MEM const PathState* states,
                                     GLOBAL_MEM const uint* camera_rngs, int stride, GLOBAL_MEM const RayMarch* ray_marches, int path,
                                     int paths, bool texel, bool first) {
#if defined(__clang__) && defined(WAVEFRONT_PREFETCH)
    if (path >= paths || (!first && !states[path].active)) return;
    EnvironmentBuffers b = scene->env_buffers;
    if (ray_marches[path].status != MARCH_HIT) {
        /* a camera ray (first step) sees the backdrop through the filtered lookup: left out */
        if (!texel || first || states[path].seen_directly) return;
        float3 d = make_float3(states[path].direction[0], states[path].direction[1], states[path].direction[2]);
        float a, c;
        __builtin_prefetch(&b.texels[environment_texel(&scene->env, d, &a, &c)]);
        return;
    }
    float2 u;
    if (!peek_environment_sample(settings, scene, first ? 0 : states[path].depth, first ? load_camera_rng(camera_rngs, stride, path) : states[path].rng, &u))
        return;
    if (texel)
        __builtin_prefetch(&b.texels[environment_sample_texel(&scene->env, b.alias, u.x, u.y)]);
    else
        __builtin_prefetch(&b.alias[environment_sample_column_entry(&scene->env, b.alias, u.x, u.y)]);
#else
    (void)settings, (void)scene, (void)states, (void)camera_rngs, (void)stride, (void)ray_marches, (void)path, (void)paths, (void)texel, (void)first;
#endif
}

/* Asks the cache for the lines of path `path`'s state that prefetch_step_environment reads (its
 * direction, depth, flags and generator: 36 to 104 bytes into the 152), sixteen paths ahead, so
 * that its peek eight paths ahead does not wait for them: without it, that first touch of the state
 * is a quarter of the peek's time in perf; the hardware's stream prefetcher does not reach so far.
 * PoCL's CPU wavefront only, as prefetch_step_environment; no bit of the image changes. */
SS_FN void prefetch_step_state(GLOBAL_MEM const PathState* states, int path, int paths) {
#if defined(__clang__) && defined(WAVEFRONT_PREFETCH)
    if (path >= paths) return;
    __builtin_prefetch(&states[path].direction[0]);
    __builtin_prefetch(&states[path].rng);
#else
    (void)states, (void)path, (void)paths;
#endif
}

/* Where the wavefront's paths leave what they gather. With one sample in flight (slots 1), path p
 * is pixel p's and adds to the film. With several (small images: more paths in flight take the
 * launches' fixed costs over more work), path slot * pixels + pixel traces sample first_sample +
 * slot of the pixel and writes its own entries, which render_pt_resolve then adds to the film in
 * sample order: film_add_path in the same order as one sample at a time, so the same bits. */
typedef struct WavefrontFilm {
    int slots;
    GLOBAL_MEM float4* accumulation; /* the film, per pixel */
    GLOBAL_MEM float4* squares;
    GLOBAL_MEM uint* ray_counts;
    GLOBAL_MEM uint* lost_ray_counts;
    GLOBAL_MEM float4* path_radiance; /* per path, slots > 1: xyz the path's radiance */
    GLOBAL_MEM uint* path_rays;
    GLOBAL_MEM uint* path_lost_rays;
} WavefrontFilm;

/* What path `path` leaves after its camera step or a step: with nothing left to march, its radiance
 * to the film; else its ray and shadow ray for the packets, and its state for the next step. Sets
 * unfinished[0] when the path still has a ray to march, unfinished[1] when it has a shadow ray:
 * every writer writes the same 1, since the host needs only whether any ray, and any shadow ray, is
 * left (it launches only those marches), and a counter's atomics cost more than the step on a CPU. */
SS_FN void path_tracer_leave(MarchSettings march_settings, int path, const PathState* p, GLOBAL_MEM PathState* states, int stride, GLOBAL_MEM float* rays,
                             GLOBAL_MEM float* shadow_rays, WavefrontFilm film, GLOBAL_MEM volatile uint* unfinished) {
    if (!p->active && !p->shadow.pending) {
        /* The path is done. All that is read of it until the next sample's camera step rewrites it
         * is that it is done: the state's two flags (the step's early return) and no ray in either
         * buffer; so only those are written, not the 152-byte state and fourteen ray fields (most
         * pixels of a simple scene end at their first or second step). With one sample in flight
         * the path is its pixel. */
        states[path].active = 0;
        states[path].shadow.pending = 0;
        store_no_ray(rays, stride, path);
        store_no_ray(shadow_rays, stride, path);
        float3 l = float3_from_array(p->radiance);
        if (film.slots > 1) {
            film.path_radiance[path] = make_float4(l.x, l.y, l.z, 0.0f);
        } else {
            float4 sum = film.accumulation[path], square_sum = film.squares[path];
            film_add_path(&sum, &square_sum, l);
            film.accumulation[path] = sum;
            film.squares[path] = square_sum;
        }
        return;
    }
    if (p->active) {
        store_ray(rays, stride, path, float3_from_array(p->origin), float3_from_array(p->direction), march_settings.max_distance);
        unfinished[0] = 1u; /* every writer writes the same 1 (above) */
    } else {
        store_no_ray(rays, stride, path);
    }
    if (p->shadow.pending) {
        store_ray(shadow_rays, stride, path, float3_from_array(p->shadow.origin), float3_from_array(p->shadow.direction),
                  shadow_max_distance(march_settings, p->shadow.distance));
        unfinished[1] = 1u;
    } else {
        store_no_ray(shadow_rays, stride, path);
    }
    states[path] = *p;
}

/* The camera step (render_pt_camera, iteration 0) of a camera the packets do not begin
 * (march_camera_rays, kernels/march_packets.cl, begins a pinhole's rays on the vector lanes): path
 * `path` (WavefrontFilm: sample first_sample + slot of pixel path - slot * pixels) draws its camera
 * ray, left for the packets, and the generator its first step begins the path with. */
SS_FN void path_tracer_camera_step(const RenderKernelSettings* settings, const Camera* camera, int path, int stride, GLOBAL_MEM float* rays,
                                   GLOBAL_MEM uint* camera_rngs) {
    const int pixels = camera->width * camera->height;
    const int slot = path / pixels, pixel = path - slot * pixels;
    Rng rng = rng_make((uint)pixel, (uint)(settings->first_sample + slot), settings->seed_lo, settings->seed_hi);
    float3 origin, direction;
    camera_pixel_ray(camera, pixel, &rng, &origin, &direction);
    store_ray(rays, stride, path, origin, direction, render_march_settings(settings).max_distance);
    store_camera_rng(camera_rngs, stride, path, rng);
}

/* A step of path `path` (render_pt_step; `first` at iteration 1): the first
 * begins the path with its camera ray (in the ray buffer) and the generator that ray left; a later
 * one resolves its pending shadow ray with its march. Then it takes the march of its ray and
 * scatters (path_scatter). */
SS_FN SS_INLINE_ALWAYS void path_tracer_step(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int path,
                                             GLOBAL_MEM PathState* states, int stride, GLOBAL_MEM float* rays, GLOBAL_MEM float* shadow_rays,
                                             GLOBAL_MEM const RayMarch* ray_marches, GLOBAL_MEM const RayMarch* shadow_marches,
                                             GLOBAL_MEM const uint* camera_rngs, WavefrontFilm film, GLOBAL_MEM volatile uint* unfinished,
                                             bool first) {
    const int paths = film.slots * camera->width * camera->height;
    /* the path's counters: the pixel's own with one sample in flight (the path is the pixel), else
     * the path's */
    GLOBAL_MEM uint* ray_count = film.slots > 1 ? &film.path_rays[path] : &film.ray_counts[path];
    GLOBAL_MEM uint* lost_ray_count = film.slots > 1 ? &film.path_lost_rays[path] : &film.lost_ray_counts[path];
    prefetch_step_state(states, path + 4 * WAVEFRONT_PREFETCH_AHEAD, paths);
    prefetch_step_environment(settings, scene, states, camera_rngs, stride, ray_marches, path + 2 * WAVEFRONT_PREFETCH_AHEAD, paths, false, first);
    prefetch_step_environment(settings, scene, states, camera_rngs, stride, ray_marches, path + WAVEFRONT_PREFETCH_AHEAD, paths, true, first);
    if (!first && !states[path].active && !states[path].shadow.pending) return; /* finished at an earlier step */
    MarchSettings march_settings = render_march_settings(settings);
    PathCounters counters = path_counters_zero();
    PathState p;
    if (first) {
        float3 origin, direction;
        load_ray(rays, stride, path, &origin, &direction);
        p = path_begin(origin, direction, load_camera_rng(camera_rngs, stride, path));
        if (film.slots > 1) *ray_count = *lost_ray_count = 0u; /* the path's counters, begun at 0 */
    } else {
        p = states[path];
    }
    if (p.shadow.pending) {
        MarchResult r = load_march(shadow_marches, path);
        count_march(r, &counters);
        path_resolve_shadow(&p, r);
    }
    if (p.active) {
        MarchResult r = load_march(ray_marches, path);
        count_march(r, &counters);
        path_scatter(settings, march_settings, scene, &p, r);
    }
    *ray_count += counters.rays;
    *lost_ray_count += counters.lost_rays;
    path_tracer_leave(march_settings, path, &p, states, stride, rays, shadow_rays, film, unfinished);
}

/* Adds the paths of `film.slots` samples in flight (slots > 1) to pixel `pixel`'s film entries, in
 * sample order. */
SS_FN void path_tracer_resolve(int pixels, int pixel, WavefrontFilm film) {
    float4 sum = film.accumulation[pixel], square_sum = film.squares[pixel];
    uint rays = film.ray_counts[pixel], lost_rays = film.lost_ray_counts[pixel];
    for (int slot = 0; slot < film.slots; ++slot) {
        int path = slot * pixels + pixel;
        float4 l = film.path_radiance[path];
        film_add_path(&sum, &square_sum, make_float3(l.x, l.y, l.z));
        rays += film.path_rays[path];
        lost_rays += film.path_lost_rays[path];
    }
    film.accumulation[pixel] = sum;
    film.squares[pixel] = square_sum;
    film.ray_counts[pixel] = rays;
    film.lost_ray_counts[pixel] = lost_rays;
}

#endif
