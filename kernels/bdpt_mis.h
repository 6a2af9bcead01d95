/* BDPT's multiple importance sampling weight of strategy (s, t) for the path it made, after
 * pbrt-v4's MISWeight: the densities with which every other strategy would have sampled the same
 * path are not formed as products (they overflow and underflow along long paths) but as running
 * ratios r_i = p_i / p_s of reverse and forward vertex densities, walking out from the connection
 * on both sides. A delta lobe or delta light makes a density 0 that no strategy can match: it is
 * remapped to 1 in the ratio, and strategies that would have to connect through such a vertex are
 * left out of the sum. Vertices at infinity (the environment) carry solid-angle densities on both
 * sides, so the ratios stay consistent. Only strategies of the kernel's mask count: `lt` (t = 1
 * alone) weighs its strategies against each other only. Strategies with more than one sample per
 * camera subpath (the light-vertex cache's, BdptKernelSettings.light_tracing_samples) enter with
 * their count: r_i = n_i p_i / (n_s p_s). Balance heuristic: 1 / sum r_i; power heuristic:
 * 1 / sum r_i^2 (r_s = 1). */
#ifndef KERNELS_BDPT_MIS_H
#define KERNELS_BDPT_MIS_H

#include "kernels/bdpt_vertex.h"

/* A forward density is 0 only after a delta lobe (the walk records it so): 1 keeps the ratios
 * going, and the delta flags leave the strategies that would need it out of the sum. */
SS_FN float bdpt_remap0(float pdf) { return pdf != 0.0f ? pdf : 1.0f; }

/* A reverse density the walk recorded as 0 because the vertex after it on its own subpath is a
 * delta lobe is remapped the same way. Any other 0 is real: no strategy that needs the vertex
 * sampled from the other side can make the path (the environment's light disk does not reach it),
 * so the ratio, and every ratio the running product carries it into, stays 0. */
SS_FN float bdpt_remap_reverse(float pdf, bool next_is_delta) { return pdf != 0.0f || !next_is_delta ? pdf : 1.0f; }

SS_FN float bdpt_heuristic(int heuristic, float r) { return heuristic == MIS_POWER ? r * r : r; }

/* q1 / q for light vertex x0 and its neighbour x1: the density with which s = 1 samples x0 from x1
 * (sample_light: a sphere seen from outside is sampled uniformly in its cone of directions, a
 * rectangle in its spherical rectangle), over the density with which a light subpath starts there
 * (uniform by area), both per unit area at x0.
 * pbrt-v4 uses q for both; with the sphere's cone sampler that makes s = 1's weight too large near
 * the cap's rim, where its real density vanishes (fireflies). 1 for point lights and the
 * environment, and for a sphere seen from inside, whose sampler is the area sampler. */
SS_FN float bdpt_light_sample_ratio(const RenderKernelSettings* settings, const RenderScene* scene, const PathVertex* x0, const PathVertex* x1) {
    int index = vertex_light_index(scene, x0);
    if (index < 0 || index >= settings->light_count) return 1.0f;
    Light light = scene->lights[index];
    if (!light_is_surface(light.type)) return 1.0f;
    float3 w = x0->p - x1->p;
    float d2 = dot(w, w);
    if (!(d2 > 0.0f)) return 1.0f;
    w = w * (1.0f / sqrt(d2));
    float q1 = light_pdf(&light, &scene->env, scene->env_buffers, x1->p, w) * fabs(dot(x0->frame.n, w)) / d2;
    float q = light_area_pdf(&light);
    return q1 > 0.0f ? q1 / q : 1.0f;
}

/* `sampled` stands in for light[0] when s = 1 (a light sample) and for camera[0] when t = 1 (a
 * lens sample); it is ignored otherwise. */
SS_FN float bdpt_mis_weight(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                            const PathVertex* cam, const PathVertex* sampled, int s, int t) {
    if (s + t == 2) return 1.0f;
    const PathVertex* qs = s == 1 ? sampled : (s > 1 ? &light[s - 1] : 0);
    const PathVertex* pt = t == 1 ? sampled : &cam[t - 1];
    const PathVertex* qs_minus = s > 1 ? &light[s - 2] : 0;
    const PathVertex* pt_minus = t > 1 ? &cam[t - 2] : 0;
    /* the reverse densities this connection gives its endpoints and their neighbours */
    float pt_rev = s > 0 ? vertex_pdf(settings, camera, scene, qs_minus, qs, pt) : vertex_pdf_light_origin(settings, scene, pt);
    float pt_minus_rev = 0.0f;
    if (t > 1) pt_minus_rev = s > 0 ? vertex_pdf(settings, camera, scene, qs, pt, pt_minus) : vertex_pdf_light(settings, scene, pt, pt_minus);
    float qs_rev = s > 0 ? vertex_pdf(settings, camera, scene, pt_minus, pt, qs) : 0.0f;
    float qs_minus_rev = s > 1 ? vertex_pdf(settings, camera, scene, pt, qs, qs_minus) : 0.0f;

    /* s = 1's own density of x0 against the light subpath's (bdpt_light_sample_ratio): a factor on
     * the ratio of strategy s' = 1 when this one is not it, its inverse on every other when it is */
    float q_ratio = 1.0f;
    if (s == 0 && t > 1) q_ratio = bdpt_light_sample_ratio(settings, scene, pt, pt_minus);
    else if (s == 1) q_ratio = bdpt_light_sample_ratio(settings, scene, qs, pt);
    else if (s >= 2) q_ratio = bdpt_light_sample_ratio(settings, scene, &light[0], &light[1]);
    /* and each strategy's samples per camera subpath (bdpt_strategy_samples): strategy i's ratio
     * is n_i p_i / (n_s p_s) */
    float n_s = bdpt_strategy_samples(&settings->bdpt, s, t);
    float own = (s == 1 ? 1.0f / q_ratio : 1.0f) / n_s; /* scales every other strategy's ratio */
    float q_ratio_s1 = q_ratio / n_s;                   /* strategy s' = 1's, when this one is not it */

    float sum = 0.0f;
    float r = 1.0f;
    for (int i = t - 1; i > 0; --i) { /* strategy (s + t - i, i) */
        /* the connection's own densities are real ones; the walk's may follow a delta lobe */
        float rev = i == t - 1 ? pt_rev : (i == t - 2 ? pt_minus_rev : cam[i].pdf_rev);
        r *= bdpt_remap_reverse(rev, i < t - 2 && cam[i + 1].delta) / bdpt_remap0(cam[i].pdf_fwd);
        bool delta = i != t - 1 && cam[i].delta;
        float q = (s + t - i == 1 ? q_ratio_s1 : own) * bdpt_strategy_samples(&settings->bdpt, s + t - i, i);
        if (!delta && !cam[i - 1].delta && bdpt_strategy_enabled(settings->bdpt.strategies, s + t - i, i)) sum += bdpt_heuristic(settings->bdpt.mis_heuristic, r * q);
    }
    r = 1.0f;
    for (int i = s - 1; i >= 0; --i) { /* strategy (i, s + t - i) */
        const PathVertex* v = i == s - 1 ? qs : &light[i];
        float rev = i == s - 1 ? qs_rev : (i == s - 2 ? qs_minus_rev : v->pdf_rev);
        r *= bdpt_remap_reverse(rev, i < s - 2 && light[i + 1].delta) / bdpt_remap0(v->pdf_fwd);
        bool delta = i != s - 1 && v->delta;
        bool delta_before = i > 0 ? light[i - 1].delta != 0 : vertex_is_delta_light(scene, i == s - 1 ? qs : &light[0]);
        float q = (i == 1 ? q_ratio_s1 : own) * bdpt_strategy_samples(&settings->bdpt, i, s + t - i);
        if (!delta && !delta_before && bdpt_strategy_enabled(settings->bdpt.strategies, i, s + t - i)) sum += bdpt_heuristic(settings->bdpt.mis_heuristic, r * q);
    }
    return 1.0f / (1.0f + sum);
}

#endif
