/* Exact ray intersection of sdf/primitives/cone.h: the capped cone with its base disk of radius r
 * in y = 0 and its apex at (0, height, 0). */
#ifndef SDF_EXACT_CONE_H
#define SDF_EXACT_CONE_H

#include "single_source/vocabulary.h"
#include "sdf/exact/cylinder.h"
#include "sdf/exact/interval.h"

/* The solid is the half-space y >= 0 intersected with the nappe rho <= k (height - y), k = r / height,
 * which opens downwards from the apex. Along the ray, with w(t) = height - y = a + b t,
 * Q(t) = |o_xz + t v_xz|^2 - k^2 w^2 = A t^2 + 2 B t + C is <= 0 on the double cone; w >= 0 keeps the
 * lower nappe. On the line, Q <= 0 is [t0, t1] when A > 0 (which w >= 0 may empty: a ray through
 * the upper nappe only), and the two ends (-inf, t0] and [t1, inf) when A < 0 (a ray steeper than
 * the slant crosses both nappes), of which w >= 0 keeps one: the later when w grows along the ray
 * (b > 0), the earlier when it shrinks. A = 0 (a ray parallel to a generator) leaves the half-line
 * 2 B t + C <= 0.
 *
 * B^2 - A C has no centre distance to be taken from, so it cancels when the terms are large: a ray
 * from 1e4 units away has C ~ 1e8. The ray is therefore first clipped to a cylinder around the cone
 * (sdf/exact/cylinder.h, robust), grown by 1 % so that its entry is never on the cone's own base,
 * and the quadric solved from that entry, where A, B and C are of the cone's size. */
SS_FN float xCone(float3 o, float3 v, float r, float height, float t_max) {
    float bound_enter, bound_exit;
    cylinder_interval(o - make_float3(0.0f, 0.5f * height, 0.0f), v, 1.01f * r, 0.505f * height, &bound_enter, &bound_exit);
    if (!(bound_enter <= bound_exit) || !(bound_exit > 0.0f)) return EXACT_MISS;
    const float lo = fmax(bound_enter, 0.0f);
    o = o + v * lo;
    float k = r / height;
    float a = height - o.y, b = -v.y;
    float A = v.x * v.x + v.z * v.z - k * k * b * b;
    float B = o.x * v.x + o.z * v.z - k * k * a * b;
    float C = o.x * o.x + o.z * o.z - k * k * a * a;
    float enter = -INFINITY, exit = INFINITY;
    if (A > 0.0f) {
        if (!exact_quadratic_roots(A, B, C, B * B - A * C, &enter, &exit)) return EXACT_MISS;
    } else if (A < 0.0f) {
        float t0, t1;
        /* -Q = -A t^2 - 2 B t - C >= 0 outside [t0, t1]; the roots are those of Q */
        if (exact_quadratic_roots(-A, -B, -C, B * B - A * C, &t0, &t1)) {
            if (b > 0.0f) enter = t1;
            else exit = t0;
        }
    } else {
        exact_clip_half_space(-C, -2.0f * B, &enter, &exit);
    }
    exact_clip_half_space(a, b, &enter, &exit);        /* w >= 0: below the apex */
    exact_clip_half_space(o.y, v.y, &enter, &exit);    /* y >= 0: above the base */
    return lo + exact_first_crossing(enter, exit, t_max - lo);
}

#ifdef SDF_LANES
/* The lane form (sdf/exact/interval.h): the three cases of A each computed, each lane taking its own;
 * o + v lo is (px, py, pz). */
SS_FN SDF_FLOAT xCone_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, float height,
                            SDF_FLOAT t_max) {
    SDF_FLOAT bound_enter, bound_exit;
    cylinder_interval_lanes(ox, oy - 0.5f * height, oz, vx, vy, vz, 1.01f * r, 0.505f * height, &bound_enter, &bound_exit);
    SDF_MASK miss = !(bound_enter <= bound_exit) || !(bound_exit > 0.0f);
    if (!SDF_ANY(!miss)) return (SDF_FLOAT)EXACT_MISS;
    const SDF_FLOAT lo = fmax(bound_enter, 0.0f);
    SDF_FLOAT px = ox + vx * lo, py = oy + vy * lo, pz = oz + vz * lo;
    float k = r / height;
    SDF_FLOAT a = height - py, b = -vy;
    SDF_FLOAT A = vx * vx + vz * vz - k * k * b * b;
    SDF_FLOAT B = px * vx + pz * vz - k * k * a * b;
    SDF_FLOAT C = px * px + pz * pz - k * k * a * a;
    SDF_FLOAT enter = -INFINITY, exit = INFINITY;
    SDF_FLOAT p0, p1, n0, n1, flat_enter = -INFINITY, flat_exit = INFINITY;
    SDF_MASK real_pos = exact_quadratic_roots_lanes(A, B, C, B * B - A * C, &p0, &p1);
    SDF_MASK real_neg = exact_quadratic_roots_lanes(-A, -B, -C, B * B - A * C, &n0, &n1);
    exact_clip_half_space_lanes(-C, -2.0f * B, &flat_enter, &flat_exit);
    SDF_MASK pos = A > 0.0f, neg = A < 0.0f;
    miss = miss || (pos && !real_pos);
    enter = select(select(flat_enter, select(enter, n1, real_neg && b > 0.0f), neg), p0, pos);
    exit = select(select(flat_exit, select(exit, n0, real_neg && !(b > 0.0f)), neg), p1, pos);
    exact_clip_half_space_lanes(a, b, &enter, &exit);
    exact_clip_half_space_lanes(py, vy, &enter, &exit);
    return select(lo + exact_first_crossing_lanes(enter, exit, t_max - lo), (SDF_FLOAT)EXACT_MISS, miss);
}
#endif

#endif
