/* BDPT with a light-vertex cache (`dtoadq render --integrator bdpt-cache`; Davidovič et al. 2014,
 * "Progressive light transport simulation on the GPU"; docs/bdpt.md, "The light-vertex cache").
 * Per sample index, in three passes over flat buffers:
 *   1. bdpt_cache_light_path: N_L light subpaths (bdpt_light_subpath), each into its own slots of
 *      the cache (max_vertices - 1 of them) with its length, and the count of its vertices a camera
 *      vertex can connect to; each also runs its t = 1 strategies (light tracing) and splats them,
 *      scaled by N_pixels / N_L;
 *   2. bdpt_cache_offsets: the counts' prefix sums, V the total;
 *   3. bdpt_cache_pixel: per pixel a camera subpath with its s = 0 and s = 1 strategies as bdpt's,
 *      and for s >= 2 each camera vertex joined to M cache vertices chosen uniformly among the V,
 *      each contribution scaled by V / (M N_L). Over the choice, (V / M) sum_m C(y_m) has the mean
 *      sum over all V vertices of C(y), so the pass estimates (1 / N_L) sum over the light subpaths
 *      of every s >= 2 strategy of each: what the per-pixel kernel estimates with one light subpath.
 * The connections, weights and subpaths are kernels/bdpt.h's, bdpt_mis.h's and bdpt_walk.h's; the
 * MIS weights count each strategy's samples per camera subpath (BdptKernelSettings'
 * light_tracing_samples, connection_samples). Everything is keyed by the sample index and the
 * light subpath's or pixel's index, never by launch order: a sample range renders the same samples
 * in any split. Needs the scene declared before it, as kernels/path.h does. */
#ifndef KERNELS_BDPT_CACHE_H
#define KERNELS_BDPT_CACHE_H

#include "kernels/vcm.h" /* merging (vcm): the same pass with a hash grid */

/* The random-number streams of the cache's passes, apart from the per-pixel kernel's (stream 0 the
 * camera subpath, 1 + a strategy's code its connection's): a light subpath's walk, and above it its
 * t = 1 strategies' lens samples, keyed by (light subpath, sample); camera vertex t's choice of
 * cache vertices (+ t), and the roulette of its m-th connection (+ 64 (m + 1) + t: t < 64), keyed
 * by (pixel, sample). */
#define BDPT_CACHE_LIGHT_STREAM 0x40000000u
#define BDPT_CACHE_CHOICE_STREAM 0x20000000u

/* Vertex k of a light subpath a camera vertex can be joined to: past the light's own vertex (s = 1
 * samples the lights afresh), on a surface that scatters. Every vertex the per-pixel kernel's
 * s >= 2 connections use, so the strategies are the same and so are their weights. */
SS_FN bool bdpt_cache_connectable(const RenderScene* scene, const PathVertex* v, int k) { return k >= 1 && vertex_scatters(scene, v); }

/* Pass 1 for light subpath `path` of `paths` and sample settings->first_sample: walks it, stores
 * it from cache[path * (max_vertices - 1)] on with its length, writes its count of connectable
 * vertices to offsets[path + 1] (pass 2 sums them), and when `splats` is set adds its t = 1
 * strategies to the splat buffer. Its rays go to its own counters, ray_counts[path]. */
SS_FN void bdpt_cache_light_path(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int path, int paths,
                                 GLOBAL_MEM PathVertex* cache, GLOBAL_MEM int* lengths, GLOBAL_MEM uint* offsets, GLOBAL_MEM uint* splat,
                                 int splats, GLOBAL_MEM uint* ray_counts, GLOBAL_MEM uint* lost_ray_counts) {
    MarchSettings march_settings = render_march_settings(settings);
    PathCounters counters = path_counters_zero();
    int slots = bdpt_kernel_max_vertices(settings) - 1; /* a light subpath's most vertices */
    uint sample = (uint)settings->first_sample;
    PathVertex light[BDPT_MAX_VERTICES];
    Rng rng = rng_make_stream((uint)path, sample, BDPT_CACHE_LIGHT_STREAM, settings->seed_lo, settings->seed_hi);
    int n_light = settings->light_count > 0 ? bdpt_light_subpath(settings, march_settings, scene, &rng, light, slots, &counters) : 0;
    uint connectable = 0u;
    for (int k = 0; k < n_light; ++k) {
        cache[path * slots + k] = light[k];
        if (bdpt_cache_connectable(scene, &light[k], k)) connectable += 1u;
    }
    lengths[path] = n_light;
    offsets[path + 1] = connectable;
    if (splats) {
        /* N_L light subpaths stand for the per-pixel kernel's one per pixel */
        float scale = (float)(camera->width * camera->height) / (float)paths;
        for (int s = 1; s <= n_light; ++s) {
            float2 raster = make_float2(-1.0f, -1.0f);
            /* no camera subpath: t = 1 samples its lens vertex */
            float3 c = bdpt_strategy_contribution(settings, march_settings, camera, scene, light, light, s, 1, slots + 1, (uint)path, sample,
                                                  BDPT_CACHE_LIGHT_STREAM + (uint)(1 + bdpt_strategy_code(s, 1)), &raster, &counters) *
                       scale;
            /* a non-finite splat has no pixel of its own to be counted in: it is left out */
            if (finite3(c) && max_component(c) > 0.0f) film_splat(splat, camera->width, camera->height, raster.x, raster.y, c);
        }
    }
    ray_counts[path] += counters.rays;
    lost_ray_counts[path] += counters.lost_rays;
}

/* Pass 2: offsets[0] = 0 and offsets[j + 1] the count of light subpath j become the prefix sums,
 * offsets[j] the number of connectable vertices before subpath j, offsets[paths] all of them (V).
 * One work-item: N_L additions. */
SS_FN void bdpt_cache_offsets(GLOBAL_MEM uint* offsets, int paths) {
    offsets[0] = 0u;
    for (int j = 1; j <= paths; ++j) offsets[j] += offsets[j - 1];
}

/* Pass 3: settings->first_sample (one sample per launch: the cache holds that sample's light
 * subpaths) of one pixel, its own part to the accumulation buffer as bdpt_pixel's. With a hash grid
 * over the cache (grid_size > 0: vcm, kernels/vcm.h) each camera vertex also merges with the cache
 * vertices near it. */
SS_FN void bdpt_cache_pixel(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int pixel,
                            GLOBAL_MEM const PathVertex* cache, GLOBAL_MEM const int* lengths, GLOBAL_MEM const uint* offsets, int paths,
                            int connections, GLOBAL_MEM const uint* grid_cells, GLOBAL_MEM const uint* grid_entries, uint grid_size,
                            GLOBAL_MEM float4* accumulation, GLOBAL_MEM float4* squares, GLOBAL_MEM uint* ray_counts,
                            GLOBAL_MEM uint* lost_ray_counts) {
    MarchSettings march_settings = render_march_settings(settings);
    PathCounters counters = path_counters_zero();
    int max_vertices = bdpt_kernel_max_vertices(settings);
    int slots = max_vertices - 1;
    uint sample = (uint)settings->first_sample;
    PathVertex cam[BDPT_MAX_VERTICES];
    PathVertex light[BDPT_MAX_VERTICES];
    Rng rng = rng_make((uint)pixel, sample, settings->seed_lo, settings->seed_hi);
    int n_cam = bdpt_camera_subpath(settings, march_settings, camera, scene, pixel, &rng, cam, max_vertices, &counters);
    uint total = offsets[paths];
    /* each chosen vertex stands for total / connections of the pool, the pool for N_L subpaths */
    float scale = (float)total / ((float)connections * (float)paths);
    float3 l = float3_splat(0.0f);
    bool finite = true;
    for (int t = 2; t <= n_cam; ++t) {
        for (int s = 0; s <= 1; ++s) {
            float2 raster;
            float3 c = bdpt_strategy_contribution(settings, march_settings, camera, scene, cam, cam, s, t, max_vertices, (uint)pixel, sample,
                                                  (uint)(1 + bdpt_strategy_code(s, t)), &raster, &counters);
            if (!finite3(c)) finite = false;
            else l += c;
        }
        if (grid_size > 0u) {
            float3 c = vcm_merge_vertex(settings, camera, scene, cam, t, max_vertices, cache, slots, paths, grid_cells, grid_entries, grid_size, light);
            if (!finite3(c)) finite = false;
            else l += c;
        }
        if (total == 0u || !vertex_scatters(scene, &cam[t - 1]) || !bdpt_strategy_enabled(settings->bdpt.strategies, 2, t)) continue;
        Rng choice = rng_make_stream((uint)pixel, sample, BDPT_CACHE_CHOICE_STREAM + (uint)t, settings->seed_lo, settings->seed_hi);
        for (int m = 0; m < connections; ++m) {
            uint v = philox_mul_hi(rng_next_uint(&choice), total); /* uniform in [0, total) */
            int lo = 0, hi = paths; /* the subpath j with offsets[j] <= v < offsets[j + 1] */
            while (hi - lo > 1) {
                int mid = (lo + hi) / 2;
                if (offsets[mid] <= v) lo = mid;
                else hi = mid;
            }
            uint rank = v - offsets[lo];
            int length = lengths[lo];
            int k = 0;
            for (int i = 1; i < length; ++i) {
                light[i] = cache[lo * slots + i];
                if (bdpt_cache_connectable(scene, &light[i], i)) {
                    if (rank == 0u) {
                        k = i;
                        break;
                    }
                    rank -= 1u;
                }
            }
            int s = k + 1;
            if (k == 0 || s + t > max_vertices) continue;
            light[0] = cache[lo * slots];
            float2 raster;
            float3 c = bdpt_strategy_contribution(settings, march_settings, camera, scene, light, cam, s, t, max_vertices, (uint)pixel, sample,
                                                  BDPT_CACHE_CHOICE_STREAM + 64u * (uint)(m + 1) + (uint)t, &raster, &counters) *
                       scale;
            if (!finite3(c)) finite = false;
            else l += c;
        }
    }
    float4 sum = accumulation[pixel], square_sum = squares[pixel];
    bdpt_add_sample(&sum, &square_sum, l, finite);
    bdpt_store_pixel(pixel, sum, square_sum, counters, accumulation, squares, ray_counts, lost_ray_counts);
}

#endif
