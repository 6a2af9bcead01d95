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
    float q = light_area_pdf(&light, scene->env_buffers, x0->p);
    return q1 > 0.0f ? q1 / q : 1.0f;
}

/* Whether vertex merging (kernels/vcm.h) can make a path at vertex v: a scattering surface whose
 * walk left it by a lobe that is no delta (the flags' rule for connections). */
SS_FN bool bdpt_merges_at(const RenderScene* scene, const PathVertex* v) { return vertex_scatters(scene, v) && !v->delta; }

/* The sum of the other strategies' (heuristic) ratios to strategy (s, t), the weight's denominator
 * less its own 1. With settings->bdpt.merge_samples > 0 (vcm) the vertex merging strategies count
 * too: merging at path vertex x is connection (s', t') whose light subpath ends just before x, times
 * merge_samples (N_L pi r^2) times the light side's density of x (Georgiev et al. 2012), and it
 * cannot merge at the light's own vertex, the lens, or a delta vertex. `merging` set: the path is
 * light vertex light[s - 1] merged with camera vertex cam[t] (kernels/vcm.h), described as
 * connection (s, t) of light[s - 1] to cam[t - 1]; the camera side's density of light[s - 1] is
 * then cam[t]'s, cam[t - 1] may be a delta vertex, and *merge_ratio receives the merge's own ratio
 * (with the connection's 1 only where the connection itself is a strategy: bdpt_mis_reference). */
SS_FN float bdpt_mis_ratio_sum(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                               const PathVertex* cam, const PathVertex* sampled, int s, int t, int merging, float* merge_ratio) {
    const PathVertex* qs = s == 1 ? sampled : (s > 1 ? &light[s - 1] : 0);
    const PathVertex* pt = t == 1 ? sampled : &cam[t - 1];
    const PathVertex* qs_minus = s > 1 ? &light[s - 2] : 0;
    const PathVertex* pt_minus = t > 1 ? &cam[t - 2] : 0;
    /* the reverse densities this connection gives its endpoints and their neighbours */
    float pt_rev = s > 0 ? vertex_pdf(settings, camera, scene, qs_minus, qs, pt) : vertex_pdf_light_origin(settings, scene, pt);
    float pt_minus_rev = 0.0f;
    if (t > 1) pt_minus_rev = s > 0 ? vertex_pdf(settings, camera, scene, qs, pt, pt_minus) : vertex_pdf_light(settings, scene, pt, pt_minus);
    float qs_rev = s > 0 ? vertex_pdf(settings, camera, scene, pt_minus, pt, qs) : 0.0f;
    if (merging) { /* the camera walk sampled the merged vertex itself, possibly through a delta lobe at pt */
        qs_rev = bdpt_remap0(cam[t].pdf_fwd);
        pt_minus_rev = bdpt_remap_reverse(pt_minus_rev, pt->delta != 0);
    }
    float eta = settings->bdpt.merge_samples;
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
        float rev_remapped = bdpt_remap_reverse(rev, i < t - 2 && cam[i + 1].delta);
        /* merging at cam[i]: the connection that ends the camera subpath there, r so far */
        if (eta > 0.0f && (s > 0 || i < t - 1) && bdpt_merges_at(scene, &cam[i]))
            sum += bdpt_heuristic(settings->bdpt.mis_heuristic, r * rev_remapped * eta * own);
        r *= rev_remapped / bdpt_remap0(cam[i].pdf_fwd);
        bool delta = (i != t - 1 || merging) && cam[i].delta;
        float q = (s + t - i == 1 ? q_ratio_s1 : own) * bdpt_strategy_samples(&settings->bdpt, s + t - i, i);
        if (!delta && !cam[i - 1].delta && bdpt_strategy_enabled(settings->bdpt.strategies, s + t - i, i)) sum += bdpt_heuristic(settings->bdpt.mis_heuristic, r * q);
    }
    r = 1.0f;
    for (int i = s - 1; i >= 0; --i) { /* strategy (i, s + t - i) */
        const PathVertex* v = i == s - 1 ? qs : &light[i];
        float rev = i == s - 1 ? qs_rev : (i == s - 2 ? qs_minus_rev : v->pdf_rev);
        float rev_remapped = bdpt_remap_reverse(rev, i < s - 2 && light[i + 1].delta);
        /* merging at light[i]: the connection that ends the light subpath there, r so far */
        if (eta > 0.0f && i >= 1 && vertex_scatters(scene, v) && (!v->delta || (merging && i == s - 1))) {
            float m = bdpt_heuristic(settings->bdpt.mis_heuristic, r * rev_remapped * eta * own);
            sum += m;
            if (merging && i == s - 1) *merge_ratio = m;
        }
        r *= rev_remapped / bdpt_remap0(v->pdf_fwd);
        bool delta = i != s - 1 && v->delta;
        bool delta_before = i > 0 ? light[i - 1].delta != 0 : vertex_is_delta_light(scene, i == s - 1 ? qs : &light[0]);
        float q = (i == 1 ? q_ratio_s1 : own) * bdpt_strategy_samples(&settings->bdpt, i, s + t - i);
        if (!delta && !delta_before && bdpt_strategy_enabled(settings->bdpt.strategies, i, s + t - i)) sum += bdpt_heuristic(settings->bdpt.mis_heuristic, r * q);
    }
    return sum;
}

/* The weight of (0, 2) or (1, 1) for a light seen directly by the lens: the camera ray that hits
 * the light at x0 (t = 2: cam[0] the lens, cam[1] x0), or the light subpath's first vertex x0
 * joined to a lens point (s = t = 1: light[0] x0, `sampled` the lens). The two are the only
 * strategies of these paths ((2, 0) would need the lens hit). r = n_(1,1) p_light(x0) / p_camera(x0),
 * both per unit area at x0, with n_(1,1) the light subpaths per camera subpath: a small bright light
 * seen directly gets its pixels' light-tracing splats (about N_pixels / its pixels of them per
 * sample) instead of one camera ray each, which is what makes its edge noisy under (0, 2) alone.
 * (1, 1) counts BDPT_DIRECT_LIGHT_SPLATS times fewer samples than it has: inside a light (0, 2)
 * has no variance (every jittered camera ray sees the same Le) while (1, 1) has its splats' count
 * noise, which the balance heuristic, blind to the variance, would mix in wherever n_(1,1) p_light
 * exceeds p_camera; with the divisor (1, 1) takes the paths where its splats per pixel per sample
 * exceed about 16 (a small light's pixels), and (0, 2) those of a large one (docs/bdpt.md, MIS).
 * The environment (at infinity; the lens is never hit from there) and emissive materials (no light
 * subpath starts on them) are (0, 2)'s alone. A point light, delta in position, is never hit by a
 * camera ray: the path tracer renders it black, and so does bdpt (weight 0); `lt`, which has no
 * (0, 2), splats it. */
#ifndef BDPT_DIRECT_LIGHT_SPLATS
#define BDPT_DIRECT_LIGHT_SPLATS 16.0f
#endif
SS_FN float bdpt_direct_light_weight(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                                     const PathVertex* cam, const PathVertex* sampled, int t) {
    int mask = settings->bdpt.strategies;
    if (!bdpt_strategy_enabled(mask, 0, 2) || !bdpt_strategy_enabled(mask, 1, 1)) return 1.0f;
    const PathVertex* lens = t == 2 ? &cam[0] : sampled;
    const PathVertex* x0 = t == 2 ? &cam[1] : &light[0];
    if (x0->type == VERTEX_ENVIRONMENT) return t == 2 ? 1.0f : 0.0f;
    if (vertex_is_delta_light(scene, x0)) return t == 2 ? 1.0f : 0.0f;
    float p_light = vertex_pdf_light_origin(settings, scene, x0) * bdpt_strategy_samples(&settings->bdpt, 1, 1);
    float p_camera = vertex_pdf(settings, camera, scene, 0, lens, x0);
    if (!(p_light > 0.0f)) return t == 2 ? 1.0f : 0.0f;
    if (!(p_camera > 0.0f)) return t == 2 ? 0.0f : 1.0f;
    p_light *= 1.0f / BDPT_DIRECT_LIGHT_SPLATS;
    float r = t == 2 ? p_light / p_camera : p_camera / p_light; /* the other strategy's over this one's */
    return 1.0f / (1.0f + bdpt_heuristic(settings->bdpt.mis_heuristic, r));
}

/* `sampled` stands in for light[0] when s = 1 and t >= 2 (a light sample) and for camera[0] when
 * t = 1 (a lens sample); it is ignored otherwise. */
SS_FN float bdpt_mis_weight(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                            const PathVertex* cam, const PathVertex* sampled, int s, int t) {
    if (s + t == 2) return bdpt_direct_light_weight(settings, camera, scene, light, cam, sampled, t);
    return 1.0f / (1.0f + bdpt_mis_ratio_sum(settings, camera, scene, light, cam, sampled, s, t, 0, 0));
}

#endif
