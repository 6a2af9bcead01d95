/* The path tracer (`dtoadq render --integrator pt`, and the preview): unidirectional paths from the
 * camera with next-event estimation to every light -- the environment, emissive spheres, point
 * lights -- combined with BSDF sampling by multiple importance sampling (power heuristic), or
 * either strategy alone (RenderKernelSettings.light_sampling). One light per vertex is chosen by
 * the host's selection distribution (power or uniform; kernels/lights/light_selection.h), and its
 * probability is part of every light density, in NEE and in the MIS weight of BSDF-sampled hits.
 *
 * Single source: kernels/path_tracer.cl runs it on OpenCL, render/host_renderer.cpp as C++ on
 * threads over pixels, with the same random numbers. Needs the scene declared before it, as
 * kernels/path.h does. */
#ifndef KERNELS_PATH_TRACER_H
#define KERNELS_PATH_TRACER_H

#include "single_source/vocabulary.h"
#include "brdf/bsdf.h"
#include "ibl/environment.h"
#include "kernels/background.h"
#include "kernels/camera.h"
#include "kernels/film.h"
#include "kernels/lights/light_selection.h"
#include "kernels/mis.h"
#include "kernels/path.h"
#include "kernels/render_scene.h"
#include "kernels/rng.h"

/* The MIS weight of a light reached by a ray sampled from the BSDF with solid-angle density
 * `bsdf_pdf`: 1 after a delta event (no light sample could have made it) or with BSDF sampling
 * alone, 0 with light sampling alone, else the power heuristic against `light_density`, the density
 * with which next-event estimation at the ray's origin samples the same direction (the light's
 * selection included; only read in that last case). */
SS_FN float light_hit_mis_weight(const RenderKernelSettings* settings, float bsdf_pdf, bool after_delta, float light_density) {
    if (after_delta || settings->light_sampling == LIGHT_SAMPLING_BSDF) return 1.0f;
    if (settings->light_sampling == LIGHT_SAMPLING_LIGHTS) return 0.0f;
    return mis_power_heuristic(bsdf_pdf, light_density);
}

/* The same for light `index` reached from `from` along `direction`: its density looked up only when
 * the weight needs it. Inlined always: out of line (as PoCL's compiler left it), its pointer to the
 * scene kept a copy of the scene in memory for every work-item of the wavefront's step. */
SS_FN SS_INLINE_ALWAYS float light_hit_weight(const RenderKernelSettings* settings, const RenderScene* scene, int index, float3 from, float3 direction,
                             float bsdf_pdf, bool after_delta) {
    if (after_delta || settings->light_sampling != LIGHT_SAMPLING_MIS) return light_hit_mis_weight(settings, bsdf_pdf, after_delta, 0.0f);
    Light light = scene->lights[index];
    float light_density = light_selection_pmf(scene->light_cdf, settings->light_count, index) *
                          light_pdf(&light, &scene->env, scene->env_buffers, from, direction);
    return light_hit_mis_weight(settings, bsdf_pdf, after_delta, light_density);
}

/* Next-event estimation at a surface point: one light chosen by the selection distribution, one
 * sample on it, and the BSDF there. Returns the shadow ray that decides whether the sample counts,
 * with its contribution: `throughput` times the estimate (pending 0 when the sample is worth
 * nothing). m: the material at the hit, clamped (material_clamped). u: xy for the light sample, z
 * for the choice of light. */
SS_FN ShadowRay direct_light_sample(const RenderKernelSettings* settings, const RenderScene* scene, const Material* m, const SurfaceHit* hit,
                                    float3 u, float3 throughput, bool catcher) {
    ShadowRay shadow;
    shadow.pending = 0;
    float pmf;
    int index = select_light(scene->light_cdf, settings->light_count, u.z, &pmf);
    if (!(pmf > 0.0f)) return shadow;
    Light light = scene->lights[index];
    LightSample ls = sample_light(&light, &scene->env, scene->env_buffers, hit->p, make_float2(u.x, u.y));
    if (!(ls.pdf > 0.0f) || !(max_component(ls.radiance) > 0.0f)) return shadow;
    float3 wl = frame_to_local(hit->frame, ls.wi);
    float3 f = bsdf_eval_clamped(m, scene->tables, hit->wo, wl);
    if (!(max_component(f) > 0.0f)) return shadow;
    float light_density = pmf * ls.pdf;
    float weight = (ls.delta || settings->light_sampling != LIGHT_SAMPLING_MIS) ? 1.0f
                                                                         : mis_power_heuristic(light_density, bsdf_pdf_clamped(m, scene->tables, hit->wo, wl));
    float3_to_array(offset_origin(hit->p, hit->frame.n, hit->epsilon, wl.z), shadow.origin);
    float3_to_array(ls.wi, shadow.direction);
    shadow.distance = ls.distance;
    shadow.target_slot = light.material_slot;
    float3 contribution = throughput * (f * ls.radiance * (fabs(wl.z) * weight / light_density));
    shadow.pending = SHADOW_COUNTS_IF_REACHED;
    if (catcher && light.type == LIGHT_ENVIRONMENT) { /* the sky the other objects hide (path_scatter) */
        contribution = -contribution;
        shadow.pending = SHADOW_COUNTS_IF_BLOCKED;
    }
    float3_to_array(contribution, shadow.contribution);
    return shadow;
}

/* A path between its vertices: what it has gathered, the ray it marches next, what the MIS weight of
 * a light that ray reaches needs, and the shadow ray of its last light sample. Vectors are float[3]
 * so that the struct has one layout on the host and in a kernel's buffer (the wavefront,
 * kernels/path_tracer_wavefront.h, keeps one per pixel between its launches). */
typedef struct PathState {
    float radiance[3], throughput[3];
    float origin[3], direction[3]; /* the ray to march next, while active */
    float previous_p[3];           /* the vertex that ray left */
    float previous_pdf;            /* the solid-angle density with which it was sampled */
    int depth;                     /* scattering events so far */
    int previous_delta;            /* it left a delta event (or the camera) */
    int seen_directly;             /* the camera ray, or only delta events since */
    int inside;                    /* it travels in a solid */
    int active;                    /* its ray is still to be marched */
    int catcher;                   /* its ray left a shadow catcher the camera sees: it adds the difference (path_scatter) */
    Rng rng;
    ShadowRay shadow;              /* pending: the last light sample, its shadow ray still to be marched */
} PathState;

SS_FN PathState path_begin(float3 origin, float3 direction, Rng rng) {
    PathState p;
    float3_to_array(float3_splat(0.0f), p.radiance);
    float3_to_array(float3_splat(1.0f), p.throughput);
    float3_to_array(origin, p.origin);
    float3_to_array(direction, p.direction);
    float3_to_array(origin, p.previous_p);
    p.previous_pdf = 0.0f;
    p.depth = 0;
    p.previous_delta = 1; /* the camera ray: nothing else could have found what it sees */
    p.seen_directly = 1;
    p.inside = scene_distance(origin) < 0.0f;
    p.active = 1;
    p.catcher = 0;
    p.rng = rng;
    p.shadow.pending = 0;
    float3_to_array(origin, p.shadow.origin); /* a defined ray where there is none */
    float3_to_array(direction, p.shadow.direction);
    return p;
}

/* The path's ray found `march_result`: adds what it sees there (the environment, an emitter), and at
 * a surface it scatters from makes the light sample (p->shadow) and samples the BSDF for its next
 * ray. Clears p->active when the path ends.
 *
 * A shadow catcher the camera ray hits is differential rendering (Debevec 1998): the pixel is the
 * backdrop behind it plus the catcher's radiance with the other objects less its radiance without
 * them, each estimated on the same path. Without them the catcher sees only the sky: so a light
 * sample of the sky counts negated where the other objects block it, one of another light counts as
 * usual (its light is theirs), and the BSDF's ray adds nothing where it escapes (the same sky either
 * way) and, where it hits an object, what that object sends less what the sky would have, with the
 * MIS weight the sky would have had. With nothing above it, every term is 0: the catcher is the
 * backdrop exactly. Reached by any other ray the catcher is an ordinary surface of its material,
 * the ground that differential rendering's local scene models. */
SS_FN void path_scatter(const RenderKernelSettings* settings, MarchSettings march_settings, const RenderScene* scene, PathState* p, MarchResult march_result) {
    float3 radiance = float3_from_array(p->radiance);
    float3 throughput = float3_from_array(p->throughput);
    float3 origin = float3_from_array(p->origin), direction = float3_from_array(p->direction);
    float3 previous_p = float3_from_array(p->previous_p);
    bool has_environment = settings->light_count > 0 && scene->lights[0].type == LIGHT_ENVIRONMENT;
    bool from_catcher = p->catcher != 0;
    p->active = 0;
    p->catcher = 0;
    if (from_catcher && has_environment) {
        if (march_result.status != MARCH_HIT) return; /* the same sky with the objects and without */
        float env_pdf;
        float3 le = environment_radiance_pdf(&scene->env, scene->env_buffers.texels, direction, &env_pdf);
        float weight = light_hit_mis_weight(settings, p->previous_pdf, p->previous_delta,
                                            light_selection_pmf(scene->light_cdf, settings->light_count, 0) * env_pdf);
        radiance -= throughput * weight * le; /* the sky this object hides */
        float3_to_array(radiance, p->radiance);
    }
    if (march_result.status != MARCH_HIT) {
        if (has_environment && p->depth == 0) {
            /* the camera ray: the backdrop (kernels/background.h); no light sample could have found it */
            if (settings->background_opacity > 0.0f) radiance += throughput * background_radiance(settings, scene, direction);
        } else if (has_environment && p->seen_directly) {
            /* what the eye sees in mirrors is filtered, so it shows no texels (it is seen after delta
             * events only: no light sample could have found it) */
            float weight = light_hit_weight(settings, scene, 0, previous_p, direction, p->previous_pdf, p->previous_delta);
            if (weight > 0.0f) radiance += throughput * weight * environment_radiance_filtered(&scene->env, scene->env_buffers.texels, direction);
        } else if (has_environment && !p->seen_directly) {
            /* the radiance and the density of the texel, from one lookup */
            float env_pdf;
            float3 le = environment_radiance_pdf(&scene->env, scene->env_buffers.texels, direction, &env_pdf);
            float weight = light_hit_mis_weight(settings, p->previous_pdf, p->previous_delta,
                                                light_selection_pmf(scene->light_cdf, settings->light_count, 0) * env_pdf);
            if (weight > 0.0f) radiance += throughput * weight * le;
        }
        float3_to_array(radiance, p->radiance);
        return;
    }
    SurfaceHit hit = surface_hit(settings, march_settings, origin, direction, march_result.t, p->inside);
    float4 emitted = scene->emission[hit.slot];
    if (emitted.w == EMISSION_SURFACE) {
#if BRDF_FEATURE_EMISSION
        /* a material's own emission (on the outer side only: from inside, wo is below the surface):
         * no light sample can find it, so the path that hits it counts it whole (weight 1),
         * whatever the light sampling */
        Material em = scene->materials[hit.slot];
        radiance += throughput * material_emission_clamped(&em, hit.wo);
        float3_to_array(radiance, p->radiance);
#endif
    } else if (emitted.w > 0.0f) { /* an emitter: a sphere from either side, a rect or disk from its emitting side */
        int index = scene->light_of_slot[hit.slot];
        Light light = scene->lights[index];
        float3 le = light_surface_radiance(&light, scene->env_buffers, hit.p, -direction);
        if (max_component(le) > 0.0f) {
            float weight = light_hit_weight(settings, scene, index, previous_p, direction, p->previous_pdf, p->previous_delta);
            radiance += throughput * (weight * le);
            float3_to_array(radiance, p->radiance);
        }
        if (emitted.w < EMISSION_SCATTERS) return; /* a black emitter scatters nothing */
        /* An emitter's material scatters on the side the ray arrives from, outside or in: a sphere
         * light is a surface, not a solid the path enters (and a rect or disk has no inside). */
        hit = facing_side(hit);
    }
    bool catcher = emitted.w == EMISSION_CATCHER && p->depth == 0;
    if (catcher && has_environment && settings->background_opacity > 0.0f) {
        radiance += throughput * background_radiance(settings, scene, direction); /* the backdrop behind it */
        float3_to_array(radiance, p->radiance);
    }
    if (p->depth >= settings->max_depth) return;

    /* bsdf_* take private pointers; the renderer clamped the scene's materials (material_clamped)
     * when it took them (render/renderer.cpp), so the vertex's three BSDF calls take it as it is */
    Material m = scene->materials[hit.slot];
    float4 u_light = rng_next4(&p->rng);
    float4 u_bsdf = rng_next4(&p->rng);
    if (settings->light_sampling != LIGHT_SAMPLING_BSDF && settings->light_count > 0)
        p->shadow = direct_light_sample(settings, scene, &m, &hit, make_float3(u_light.x, u_light.y, u_light.w), throughput, catcher);

    BsdfSample b = bsdf_sample_clamped(&m, scene->tables, hit.wo, make_float3(u_bsdf.x, u_bsdf.y, u_bsdf.z));
    if (b.flags == 0) return;
    throughput *= b.f * (fabs(b.wi.z) / b.pdf);
    float3_to_array(hit.p, p->previous_p);
    p->previous_pdf = b.pdf;
    p->previous_delta = (b.flags & BSDF_DELTA) != 0;
    p->seen_directly = p->seen_directly && p->previous_delta;
    p->catcher = catcher;
    if ((b.flags & BSDF_TRANSMISSION) != 0) p->inside = !p->inside;
    float3_to_array(offset_origin(hit.p, hit.frame.n, hit.epsilon, b.wi.z), p->origin);
    float3_to_array(frame_to_world(hit.frame, b.wi), p->direction);

    /* Russian roulette keeps a path with probability min(1, max throughput): a path whose
     * throughput stays 1 (white furnace) is never cut, so the estimator's variance is not raised
     * where nothing is absorbed. */
    if (p->depth + 1 >= settings->roulette_depth) {
        float survive = fmin(max_component(throughput), 1.0f);
        if (!(u_light.z < survive)) return;
        throughput /= survive;
    }
    float3_to_array(throughput, p->throughput);
    p->depth += 1;
    p->active = 1;
}

/* The march of the path's pending shadow ray: its light sample counts if the ray got there. */
SS_FN void path_resolve_shadow(PathState* p, MarchResult r) {
    bool counts_if_reached = p->shadow.pending == SHADOW_COUNTS_IF_REACHED;
    p->shadow.pending = 0;
    if (shadow_reached(&p->shadow, r) == counts_if_reached) float3_to_array(float3_from_array(p->radiance) + float3_from_array(p->shadow.contribution), p->radiance);
}

/* Radiance arriving at `origin` from `direction`, estimated by one path drawing its numbers from
 * `rng`: each vertex's shadow ray is marched right after it scatters. */
SS_FN float3 trace_path(const RenderKernelSettings* settings, MarchSettings march_settings, const RenderScene* scene, float3 origin, float3 direction, Rng rng,
                        PathCounters* counters) {
    PathState p = path_begin(origin, direction, rng);
    for (;;) {
        path_scatter(settings, march_settings, scene, &p, trace_ray(float3_from_array(p.origin), float3_from_array(p.direction), march_settings, counters));
        if (p.shadow.pending) path_resolve_shadow(&p, trace_shadow_ray(&p.shadow, march_settings, counters));
        if (!p.active) break;
    }
    return float3_from_array(p.radiance);
}

/* A pixel's sum and sum of squares (kernels/film.h) with one more path's radiance; a path that is
 * not finite is counted in sum.w instead (the film reports them). */
SS_FN void film_add_path(float4* sum, float4* squares, float3 l) {
    if (finite3(l)) {
        *sum += make_float4(l.x, l.y, l.z, 0.0f);
        *squares = film_add_square(*squares, l);
    } else {
        sum->w += 1.0f;
    }
}

/* Adds settings->sample_count samples to one pixel; pixel k is (k % width, k / width), row 0 at the
 * top. The samples of a pixel are summed in sample order by the one work-item that owns it. */
SS_FN void path_tracer_pixel(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int pixel,
                             GLOBAL_MEM float4* accumulation, GLOBAL_MEM float4* squares, GLOBAL_MEM uint* ray_counts,
                             GLOBAL_MEM uint* lost_ray_counts) {
    MarchSettings march_settings = render_march_settings(settings);
    float4 sum = accumulation[pixel], square_sum = squares[pixel];
    PathCounters counters = path_counters_zero();
    for (int i = 0; i < settings->sample_count; ++i) {
        Rng rng = rng_make((uint)pixel, (uint)(settings->first_sample + i), settings->seed_lo, settings->seed_hi);
        float3 origin, direction;
        camera_pixel_ray(camera, pixel, &rng, &origin, &direction);
        film_add_path(&sum, &square_sum, trace_path(settings, march_settings, scene, origin, direction, rng, &counters));
    }
    accumulation[pixel] = sum;
    squares[pixel] = square_sum;
    ray_counts[pixel] += counters.rays;
    lost_ray_counts[pixel] += counters.lost_rays;
}

#endif
