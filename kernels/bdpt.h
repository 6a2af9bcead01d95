/* Bidirectional path tracing (`dtoadq render --integrator bdpt`, and `lt`, its t = 1 strategies
 * alone), after pbrt-v4's BDPTIntegrator; docs/bdpt.md. Per sample of a pixel: one camera subpath
 * through the pixel, one light subpath, and every connection (s, t) of s light vertices to t camera
 * vertices with s + t <= max_vertices that the strategy mask enables:
 *   s = 0   the camera subpath reaches a light (an emissive sphere or the environment);
 *   s = 1   a fresh light sample joined to a camera vertex (next-event estimation);
 *   s >= 2  two subpath vertices joined through a visibility march;
 *   t = 1   a light vertex joined to a fresh point on the lens, splatted where it lands on the film.
 * Each is weighted by kernels/bdpt_mis.h. The own pixel's sum goes to the accumulation buffer, t = 1
 * to the splat buffer (kernels/film.h). One work-item per pixel runs the whole sample (a
 * megakernel): docs/bdpt.md says why, measured against the alternatives.
 *
 * Single source: kernels/bdpt.cl runs it on OpenCL, render/host_renderer.cpp as C++. Needs the
 * scene declared before it, as kernels/path.h does. */
#ifndef KERNELS_BDPT_H
#define KERNELS_BDPT_H

#include "kernels/background.h"
#include "kernels/bdpt_mis.h"
#include "kernels/bdpt_walk.h"
#include "kernels/film.h"

/* Whether a segment from surface vertex a to surface vertex b is clear. The march starts off a's
 * surface and stops at b's within the error the march itself allows there (its hit threshold, over
 * the cosine at b: a grazing arrival stops short of b by that much). */
SS_FN bool bdpt_surfaces_see_each_other(const PathVertex* a, const PathVertex* b, MarchSettings march_settings, PathCounters* counters) {
    float3 w = b->p - a->p;
    float dist = length(w);
    if (!(dist > 0.0f)) return false;
    w = w / dist;
    float3 origin = offset_origin(a->p, a->frame.n, a->epsilon, dot(a->frame.n, w));
    march_settings.max_distance = fmin(march_settings.max_distance, dist);
    MarchResult r = trace_ray(origin, w, march_settings, counters);
    if (r.status == MARCH_MISS) return true;
    if (r.status != MARCH_HIT) return false;
    float gap = length(origin + w * r.t - b->p) * fabs(dot(b->frame.n, w));
    return gap <= 4.0f * fmax(b->epsilon, march_epsilon(march_settings, r.t));
}

/* The origin of a shadow ray from vertex v along unit w: off the surface on w's side. */
SS_FN float3 bdpt_ray_origin(const PathVertex* v, float3 w) {
    return v->on_surface ? offset_origin(v->p, v->frame.n, v->epsilon, dot(v->frame.n, w)) : v->p;
}

/* The unweighted contribution of strategy (s, t) and, through *weight, its MIS weight; t = 1 sets
 * *raster to where it lands. Zero where the strategy cannot make a path from these subpaths. The
 * weight needs no ray, so it comes before the connection's visibility march: a connection of
 * weight 0 traces none, and one whose weight w is below settings->bdpt.connection_roulette
 * traces it with probability w / connection_roulette (drawn from rng) and counts 1 / that
 * probability when it does (connection roulette, docs/bdpt.md). */
SS_FN float3 bdpt_connect(const RenderKernelSettings* settings, MarchSettings march_settings, const Camera* camera, const RenderScene* scene,
                          const PathVertex* light, const PathVertex* cam, int s, int t, Rng* rng, float2* raster, float* weight,
                          PathCounters* counters) {
    float3 zero = float3_splat(0.0f);
    *weight = 0.0f;
    if (t > 1 && s != 0 && cam[t - 1].type == VERTEX_ENVIRONMENT) return zero; /* nothing connects to infinity */
    PathVertex sampled;
    float3 L;
    /* the shadow ray of s = 1 and t = 1, traced after the weight */
    float3 ray_origin = zero, ray_direction = zero;
    float ray_distance = 0.0f;
    int ray_target = -1;
    if (s == 0) {
        const PathVertex* pt = &cam[t - 1];
        if (!vertex_emits(scene, pt)) return zero;
        bool seen_directly = true; /* through delta lobes only, as the path tracer's backdrop */
        for (int i = 1; i < t - 1; ++i) seen_directly = seen_directly && cam[i].delta;
        if (pt->type == VERTEX_ENVIRONMENT && t == 2) { /* the camera ray: the backdrop (kernels/background.h) */
            if (!(settings->background_opacity > 0.0f)) return zero;
            L = pt->beta * background_radiance(settings, scene, pt->p);
        } else {
            L = pt->beta * vertex_le(scene, pt, seen_directly);
        }
    } else if (t == 1) {
        const PathVertex* qs = &light[s - 1];
        if (qs->type == VERTEX_ENVIRONMENT || (qs->type == VERTEX_SURFACE && !vertex_scatters(scene, qs))) return zero;
        float4 u = rng_next4(rng);
        CameraSample cs = camera_sample_wi(camera, qs->p, make_float2(u.x, u.y));
        if (!cs.visible) return zero;
        sampled = camera_vertex(camera, cs.lens_point, float3_splat(cs.importance / cs.pdf));
        float3 f = qs->type == VERTEX_SURFACE ? vertex_f(scene, qs, cs.wi, TRANSPORT_IMPORTANCE) : float3_splat(1.0f);
        float cos_q = qs->on_surface ? fabs(dot(qs->frame.n, cs.wi)) : 1.0f;
        L = qs->beta * f * sampled.beta * cos_q;
        if (!(max_component(L) > 0.0f)) return zero;
        ray_origin = bdpt_ray_origin(qs, cs.wi);
        ray_direction = cs.wi;
        ray_distance = cs.distance;
        *raster = cs.raster;
    } else if (s == 1) {
        const PathVertex* pt = &cam[t - 1];
        if (!vertex_scatters(scene, pt)) return zero;
        float4 u = rng_next4(rng);
        float pmf;
        int index = select_light(scene->light_cdf, settings->light_count, u.z, &pmf);
        if (!(pmf > 0.0f)) return zero;
        Light l = scene->lights[index];
        /* On an emissive sphere itself, the hit can lie a rounding error on the far side of the
         * surface from the path, where the sphere's own sampler would see only a vanishing cap
         * around it: sample from the point just off the surface on the path's side instead. */
        float3 p_ref = vertex_emits(scene, pt) ? offset_origin(pt->p, pt->frame.n, pt->epsilon, 1.0f) : pt->p;
        LightSample ls = sample_light(&l, &scene->env, scene->env_buffers, p_ref, make_float2(u.x, u.y));
        if (!(ls.pdf > 0.0f) || !(max_component(ls.radiance) > 0.0f)) return zero;
        sampled.type = l.type == LIGHT_ENVIRONMENT ? VERTEX_ENVIRONMENT : VERTEX_LIGHT;
        sampled.p = l.type == LIGHT_ENVIRONMENT ? ls.wi : ls.position;
        sampled.frame = frame_from_normal(ls.normal);
        sampled.on_surface = light_is_surface(l.type);
        sampled.index = index;
        sampled.delta = 0;
        sampled.epsilon = 0.0f;
        sampled.beta = ls.radiance / (pmf * ls.pdf);
        sampled.pdf_rev = 0.0f;
        sampled.pdf_fwd = vertex_pdf_light_origin(settings, scene, &sampled);
        L = pt->beta * vertex_f(scene, pt, ls.wi, TRANSPORT_RADIANCE) * sampled.beta * fabs(dot(ls.wi, pt->frame.n));
        if (!(max_component(L) > 0.0f)) return zero;
        ray_origin = bdpt_ray_origin(pt, ls.wi);
        ray_direction = ls.wi;
        ray_distance = ls.distance;
        ray_target = l.material_slot;
    } else {
        const PathVertex* qs = &light[s - 1];
        const PathVertex* pt = &cam[t - 1];
        if (!vertex_scatters(scene, qs) || !vertex_scatters(scene, pt)) return zero;
        float3 w = pt->p - qs->p;
        float d2 = dot(w, w);
        if (!(d2 > 0.0f)) return zero;
        w = w * (1.0f / sqrt(d2));
        float g = fabs(dot(qs->frame.n, w)) * fabs(dot(pt->frame.n, w)) / d2;
        L = qs->beta * vertex_f(scene, qs, w, TRANSPORT_IMPORTANCE) * vertex_f(scene, pt, -w, TRANSPORT_RADIANCE) * pt->beta * g;
        if (!(max_component(L) > 0.0f)) return zero;
    }
    float w = bdpt_mis_weight(settings, camera, scene, light, cam, &sampled, s, t);
    if (s != 0) { /* the connection's visibility march, unless its weight leaves it out */
        if (w == 0.0f) return zero;
        float roulette = settings->bdpt.connection_roulette;
        if (w < roulette) {
            float survive = w / roulette;
            if (!(uint_to_unit_float(rng_next_uint(rng)) < survive)) return zero;
            L = L / survive;
        }
        bool visible = s >= 2 && t >= 2 ? bdpt_surfaces_see_each_other(&light[s - 1], &cam[t - 1], march_settings, counters)
                                        : segment_unoccluded(ray_origin, ray_direction, ray_distance, ray_target, march_settings, counters);
        if (!visible) return zero;
    }
    *weight = w;
    return L;
}

/* Strategy (s, t) of a path with these subpaths, MIS-weighted (unless the settings ask for it
 * unweighted), where the render adds it; zero where it does not (outside max_vertices, the mask,
 * or the one strategy --strategies renders). t = 1 sets *raster to where it lands. A connection
 * (s >= 1) draws its light sample (s = 1), lens sample (t = 1) and connection roulette from a
 * stream of its own, (key, sample, stream): a strategy rendered alone (--strategies) draws what it
 * draws in the whole render, so the strategy images add up to the render. */
SS_FN float3 bdpt_strategy_contribution(const RenderKernelSettings* settings, MarchSettings march_settings, const Camera* camera,
                                        const RenderScene* scene, const PathVertex* light, const PathVertex* cam, int s, int t,
                                        int max_vertices, uint key, uint sample, uint stream, float2* raster, PathCounters* counters) {
    float3 zero = float3_splat(0.0f);
    if (s + t < 2 || s + t > max_vertices) return zero;
    if (!bdpt_strategy_enabled(settings->bdpt.strategies, s, t)) return zero;
    if (settings->bdpt.single_strategy >= 0 && settings->bdpt.single_strategy != bdpt_strategy_code(s, t)) return zero;
    Rng connection_rng = rng_make_stream(key, sample, stream, settings->seed_lo, settings->seed_hi);
    float weight;
    float3 c = bdpt_connect(settings, march_settings, camera, scene, light, cam, s, t, &connection_rng, raster, &weight, counters);
    return settings->bdpt.unweighted ? c : c * weight;
}

/* The most vertices of this kernel's paths: the settings' max_vertices, within the private arrays. */
SS_FN int bdpt_kernel_max_vertices(const RenderKernelSettings* settings) { return min(max(settings->bdpt.max_vertices, 2), BDPT_MAX_VERTICES); }

/* A sample's own-pixel radiance l into the pixel's sums; a sample with a non-finite contribution
 * or weight only counted in sum.w (the film divides by the finite samples). */
SS_FN void bdpt_add_sample(float4* sum, float4* square_sum, float3 l, bool finite) {
    if (finite) {
        *sum += make_float4(l.x, l.y, l.z, 0.0f);
        *square_sum = film_add_square(*square_sum, l);
    } else {
        sum->w += 1.0f;
    }
}

/* A pixel's sums and its rays back into the film's buffers. */
SS_FN void bdpt_store_pixel(int pixel, float4 sum, float4 square_sum, PathCounters counters, GLOBAL_MEM float4* accumulation,
                            GLOBAL_MEM float4* squares, GLOBAL_MEM uint* ray_counts, GLOBAL_MEM uint* lost_ray_counts) {
    accumulation[pixel] = sum;
    squares[pixel] = square_sum;
    ray_counts[pixel] += counters.rays;
    lost_ray_counts[pixel] += counters.lost_rays;
}

/* Adds settings->sample_count samples to one pixel (pixel k is (k % width, k / width)), its t = 1
 * connections to the splat buffer. The sum of squares holds the own pixel's part of each sample:
 * the splats' variance is not in it. A sample with a non-finite contribution or MIS weight is counted
 * in accumulation.w and its own pixel's sum left out, as the path tracer's are (the film divides
 * by the finite samples; the statistics report the count). */
SS_FN void bdpt_pixel(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int pixel,
                      GLOBAL_MEM float4* accumulation, GLOBAL_MEM float4* squares, GLOBAL_MEM uint* splat, GLOBAL_MEM uint* ray_counts,
                      GLOBAL_MEM uint* lost_ray_counts) {
    MarchSettings march_settings = render_march_settings(settings);
    float4 sum = accumulation[pixel], square_sum = squares[pixel];
    PathCounters counters = path_counters_zero();
    int max_vertices = bdpt_kernel_max_vertices(settings);
    PathVertex cam[BDPT_MAX_VERTICES];
    PathVertex light[BDPT_MAX_VERTICES];
    for (int i = 0; i < settings->sample_count; ++i) {
        uint sample = (uint)(settings->first_sample + i);
        Rng rng = rng_make((uint)pixel, sample, settings->seed_lo, settings->seed_hi);
        /* t = 1 alone (the light tracer) needs no camera subpath: its lens vertex is sampled per connection */
        bool camera_strategies = (settings->bdpt.strategies & (STRATEGY_S0 | STRATEGY_S1 | STRATEGY_S2)) != 0;
        int n_cam = camera_strategies ? bdpt_camera_subpath(settings, march_settings, camera, scene, pixel, &rng, cam, max_vertices, &counters) : 1;
        int n_light = settings->light_count > 0 ? bdpt_light_subpath(settings, march_settings, scene, &rng, light, max_vertices - 1, &counters) : 0;
        float3 l = float3_splat(0.0f);
        bool finite = true;
        for (int t = 1; t <= n_cam; ++t)
            for (int s = 0; s <= n_light; ++s) {
                float2 raster = make_float2(-1.0f, -1.0f);
                float3 c = bdpt_strategy_contribution(settings, march_settings, camera, scene, light, cam, s, t, max_vertices, (uint)pixel, sample,
                                                      (uint)(1 + bdpt_strategy_code(s, t)), &raster, &counters);
                /* a NaN or infinite contribution or weight is counted before anything can drop it */
                if (!finite3(c)) {
                    finite = false;
                    continue;
                }
                if (!(max_component(c) > 0.0f)) continue;
                if (t == 1) film_splat(splat, camera->width, camera->height, raster.x, raster.y, c);
                else l += c;
            }
        bdpt_add_sample(&sum, &square_sum, l, finite);
    }
    bdpt_store_pixel(pixel, sum, square_sum, counters, accumulation, squares, ray_counts, lost_ray_counts);
}

#endif
