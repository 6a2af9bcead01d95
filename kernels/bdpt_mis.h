/* BDPT's multiple importance sampling weight of strategy (s, t) for the path it made, after
 * pbrt-v4's MISWeight: the densities with which every other strategy would have sampled the same
 * path are not formed as products (they overflow and underflow along long paths) but as running
 * ratios r_i = p_i / p_s of reverse and forward vertex densities, walking out from the connection
 * on both sides. A delta lobe or delta light makes a density 0 that no strategy can match: it is
 * remapped to 1 in the ratio, and strategies that would have to connect through such a vertex are
 * left out of the sum. Vertices at infinity (the environment) carry solid-angle densities on both
 * sides, so the ratios stay consistent. Only strategies of the kernel's mask count: `lt` (t = 1
 * alone) weighs its strategies against each other only. Balance heuristic: 1 / sum r_i; power
 * heuristic: 1 / sum r_i^2 (r_s = 1). */
#ifndef KERNELS_BDPT_MIS_H
#define KERNELS_BDPT_MIS_H

#include "kernels/bdpt_vertex.h"

SS_FN float bdpt_remap0(float pdf) { return pdf != 0.0f ? pdf : 1.0f; }

SS_FN bool bdpt_strategy_enabled(int mask, int s, int t) {
    if (t == 1) return (mask & STRATEGY_T1) != 0;
    if (t < 1) return false; /* the lens is never hit */
    if (s == 0) return (mask & STRATEGY_S0) != 0;
    if (s == 1) return (mask & STRATEGY_S1) != 0;
    return (mask & STRATEGY_S2) != 0;
}

SS_FN float bdpt_heuristic(int heuristic, float r) { return heuristic == MIS_POWER ? r * r : r; }

/* `sampled` stands in for light[0] when s = 1 (a light sample) and for camera[0] when t = 1 (a
 * lens sample); it is ignored otherwise. */
SS_FN float bdpt_mis_weight(const RenderKernelSettings* k, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                            const PathVertex* cam, const PathVertex* sampled, int s, int t) {
    if (s + t == 2) return 1.0f;
    const PathVertex* qs = s == 1 ? sampled : (s > 1 ? &light[s - 1] : 0);
    const PathVertex* pt = t == 1 ? sampled : &cam[t - 1];
    const PathVertex* qs_minus = s > 1 ? &light[s - 2] : 0;
    const PathVertex* pt_minus = t > 1 ? &cam[t - 2] : 0;
    /* the reverse densities this connection gives its endpoints and their neighbours */
    float pt_rev = s > 0 ? vertex_pdf(k, camera, scene, qs_minus, qs, pt) : vertex_pdf_light_origin(k, scene, pt);
    float pt_minus_rev = 0.0f;
    if (t > 1) pt_minus_rev = s > 0 ? vertex_pdf(k, camera, scene, qs, pt, pt_minus) : vertex_pdf_light(k, scene, pt, pt_minus);
    float qs_rev = s > 0 ? vertex_pdf(k, camera, scene, pt_minus, pt, qs) : 0.0f;
    float qs_minus_rev = s > 1 ? vertex_pdf(k, camera, scene, pt, qs, qs_minus) : 0.0f;

    float sum = 0.0f;
    float r = 1.0f;
    for (int i = t - 1; i > 0; --i) { /* strategy (s + t - i, i) */
        float rev = i == t - 1 ? pt_rev : (i == t - 2 ? pt_minus_rev : cam[i].pdf_rev);
        r *= bdpt_remap0(rev) / bdpt_remap0(cam[i].pdf_fwd);
        bool delta = i != t - 1 && cam[i].delta;
        if (!delta && !cam[i - 1].delta && bdpt_strategy_enabled(k->strategies, s + t - i, i)) sum += bdpt_heuristic(k->mis_heuristic, r);
    }
    r = 1.0f;
    for (int i = s - 1; i >= 0; --i) { /* strategy (i, s + t - i) */
        const PathVertex* v = i == s - 1 ? qs : &light[i];
        float rev = i == s - 1 ? qs_rev : (i == s - 2 ? qs_minus_rev : v->pdf_rev);
        r *= bdpt_remap0(rev) / bdpt_remap0(v->pdf_fwd);
        bool delta = i != s - 1 && v->delta;
        bool delta_before = i > 0 ? light[i - 1].delta != 0 : vertex_is_delta_light(scene, i == s - 1 ? qs : &light[0]);
        if (!delta && !delta_before && bdpt_strategy_enabled(k->strategies, i, s + t - i)) sum += bdpt_heuristic(k->mis_heuristic, r);
    }
    return 1.0f / (1.0f + sum);
}

#endif
