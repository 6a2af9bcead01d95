/* Surface normals of the scene: finite differences of scene_distance, or the nearest object's
 * analytic normal. Needs `float scene_distance(float3 p)` and
 * `int scene_analytic_normal(float3 p, float3* n)` declared before this header is included (the
 * generated scene source defines both; on the host see sdf/sdf.hpp). */
#ifndef SDF_NORMALS_H
#define SDF_NORMALS_H

#include "single_source/vocabulary.h"

#define NORMAL_TETRAHEDRAL 0
#define NORMAL_CENTRAL 1
#define NORMAL_ANALYTIC 2

/* normalize(g), or +y when g vanishes or is not finite (a point where the field is flat, e.g. the
 * centre of a sphere), so a normal is always a unit vector. */
SS_FN float3 normal_from_gradient(float3 g) {
    float l = length(g);
    if (!(l > 0.0f) || !isfinite_f(l)) return make_float3(0.0f, 1.0f, 0.0f);
    return g / l;
}

/* Four evaluations at the vertices k of a tetrahedron, k in {(1,-1,-1), (-1,-1,1), (-1,1,-1),
 * (1,1,1)}. The k sum to zero and sum_k k k^T = 4 I; every k has kx ky kz = 1, so the second-order
 * terms leave the off-diagonal Hessian H:
 *   sum_k k f(p + h k) = 4 h grad f + 4 h^2 (H_yz, H_xz, H_xy) + O(h^3).
 * The direction is therefore off by O(h |H| / |grad f|) -- first order, from curvature not aligned
 * with the axes (none on planes and axis-aligned faces) -- at 4 evaluations instead of 6. */
SS_FN float3 normal_tetrahedral(float3 p, float h) {
    float3 k0 = make_float3(1.0f, -1.0f, -1.0f);
    float3 k1 = make_float3(-1.0f, -1.0f, 1.0f);
    float3 k2 = make_float3(-1.0f, 1.0f, -1.0f);
    float3 k3 = make_float3(1.0f, 1.0f, 1.0f);
    float3 g = k0 * scene_distance(p + k0 * h) + k1 * scene_distance(p + k1 * h) +
               k2 * scene_distance(p + k2 * h) + k3 * scene_distance(p + k3 * h);
    return normal_from_gradient(g);
}

/* Central differences along the axes, six evaluations: (f(p + h e_i) - f(p - h e_i)) / 2h =
 * df/dx_i + O(h^2): second order, so more accurate than the tetrahedral normal on curved surfaces
 * (until float rounding of f, about 1e-7 |p| / h, takes over). */
SS_FN float3 normal_central(float3 p, float h) {
    float3 ex = make_float3(h, 0.0f, 0.0f);
    float3 ey = make_float3(0.0f, h, 0.0f);
    float3 ez = make_float3(0.0f, 0.0f, h);
    float3 g = make_float3(scene_distance(p + ex) - scene_distance(p - ex), scene_distance(p + ey) - scene_distance(p - ey),
                           scene_distance(p + ez) - scene_distance(p - ez));
    return normal_from_gradient(g);
}

/* The normal by the chosen method; NORMAL_ANALYTIC uses the nearest object's analytic normal and
 * falls back to the tetrahedral one where scene_analytic_normal returns 0 (no analytic normal, or
 * the nearest object is a blend or displaced). */
SS_FN float3 scene_normal(float3 p, float h, int method) {
    if (method == NORMAL_ANALYTIC) {
        float3 n;
        if (scene_analytic_normal(p, &n)) return n;
        return normal_tetrahedral(p, h);
    }
    if (method == NORMAL_CENTRAL) return normal_central(p, h);
    return normal_tetrahedral(p, h);
}

#endif
