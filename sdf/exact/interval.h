/* What every exact intersection (sdf/exact/) shares. A ray o + t v (v unit) meets a convex solid in
 * one interval [enter, exit] of t; its first crossing of the surface after the origin is `enter`
 * from outside and `exit` from inside (a ray that leaves a solid, for refraction). Every xShape
 * function returns that crossing when it lies in (0, t_max], else EXACT_MISS. */
#ifndef SDF_EXACT_INTERVAL_H
#define SDF_EXACT_INTERVAL_H

#include "single_source/vocabulary.h"

#define EXACT_MISS INFINITY

/* The first crossing of a convex solid's surface, given its interval (empty when enter > exit or a
 * bound is NaN). */
SS_FN float exact_first_crossing(float enter, float exit, float t_max) {
    if (!(enter <= exit)) return EXACT_MISS;
    float t = enter > 0.0f ? enter : exit;
    return t > 0.0f && t <= t_max ? t : EXACT_MISS;
}

/* The roots t0 <= t1 of a t^2 + 2 b t + c, given disc = b^2 - a c computed by the caller in a form
 * that keeps its precision (Haines et al. 2019, "Precision Improvements for Ray/Sphere
 * Intersection": from the distance of the axis or centre to the ray, not from b^2 - a c). The root
 * of larger magnitude is q / a with q = -(b + sign(b) sqrt(disc)), the other c / q: no difference
 * of nearly equal numbers. 0 when disc < 0 (no real root). a > 0. */
SS_FN int exact_quadratic_roots(float a, float b, float c, float disc, float* t0, float* t1) {
    if (!(disc >= 0.0f)) return 0;
    float s = sqrt(disc);
    float q = -(b + (b >= 0.0f ? s : -s));
    if (q == 0.0f) { /* b = 0 and disc = 0: a double root at 0 */
        *t0 = *t1 = 0.0f;
        return 1;
    }
    float r0 = q / a, r1 = c / q;
    *t0 = fmin(r0, r1);
    *t1 = fmax(r0, r1);
    return 1;
}

/* Narrows [*enter, *exit] to where c0 + c1 t >= 0 (a half-space along the ray). */
SS_FN void exact_clip_half_space(float c0, float c1, float* enter, float* exit) {
    if (c1 > 0.0f) *enter = fmax(*enter, -c0 / c1);
    else if (c1 < 0.0f) *exit = fmin(*exit, -c0 / c1);
    else if (c0 < 0.0f) *enter = INFINITY; /* parallel and outside */
}

/* Narrows [*enter, *exit] to the slab lo <= o + t v <= hi of one axis (Kay and Kajiya 1986). A
 * component v = 0 divides to +-INFINITY, which fmin / fmax take as they should; 0 / 0 (the ray in
 * the slab's face) is a NaN they drop, so such a ray counts as outside. */
SS_FN void exact_clip_slab(float lo, float hi, float o, float v, float* enter, float* exit) {
    float t0 = (lo - o) / v, t1 = (hi - o) / v;
    *enter = fmax(*enter, fmin(t0, t1));
    *exit = fmin(*exit, fmax(t0, t1));
}

/* The union of a convex piece's interval with the one so far, for a convex solid made of
 * overlapping convex pieces (capsule, rounded box): the ray meets a convex union in one interval,
 * which is the union of the pieces' intervals, so its ends are the least entry and the greatest
 * exit of the pieces it meets. */
SS_FN void exact_union_interval(float enter, float exit, float* union_enter, float* union_exit) {
    if (!(enter <= exit)) return;
    *union_enter = fmin(*union_enter, enter);
    *union_exit = fmax(*union_exit, exit);
}

#ifdef SDF_LANES
/* The lane forms (a packet kernel's eight rays, single_source/vocabulary.h): the functions above
 * line for line, each branch a select of the same values, so every lane rounds as the scalar form. */

SS_FN SDF_FLOAT exact_first_crossing_lanes(SDF_FLOAT enter, SDF_FLOAT exit, SDF_FLOAT t_max) {
    SDF_FLOAT t = select(exit, enter, enter > 0.0f);
    return select((SDF_FLOAT)EXACT_MISS, t, enter <= exit && t > 0.0f && t <= t_max);
}

/* The lanes with real roots; the others' *t0, *t1 are not to be read. */
SS_FN SDF_MASK exact_quadratic_roots_lanes(SDF_FLOAT a, SDF_FLOAT b, SDF_FLOAT c, SDF_FLOAT disc, SDF_FLOAT* t0, SDF_FLOAT* t1) {
    SDF_FLOAT s = sqrt(disc);
    SDF_FLOAT q = -(b + select(-s, s, b >= 0.0f));
    SDF_FLOAT r0 = q / a, r1 = c / q;
    *t0 = select(fmin(r0, r1), (SDF_FLOAT)0.0f, q == 0.0f);
    *t1 = select(fmax(r0, r1), (SDF_FLOAT)0.0f, q == 0.0f);
    return disc >= 0.0f;
}

SS_FN void exact_clip_half_space_lanes(SDF_FLOAT c0, SDF_FLOAT c1, SDF_FLOAT* enter, SDF_FLOAT* exit) {
    SDF_FLOAT t = -c0 / c1;
    *enter = select(*enter, fmax(*enter, t), c1 > 0.0f);
    *exit = select(*exit, fmin(*exit, t), c1 < 0.0f);
    *enter = select(*enter, (SDF_FLOAT)INFINITY, !(c1 > 0.0f) && !(c1 < 0.0f) && c0 < 0.0f);
}

SS_FN void exact_union_interval_lanes(SDF_FLOAT enter, SDF_FLOAT exit, SDF_FLOAT* union_enter, SDF_FLOAT* union_exit) {
    SDF_MASK met = enter <= exit;
    *union_enter = select(*union_enter, fmin(*union_enter, enter), met);
    *union_exit = select(*union_exit, fmax(*union_exit, exit), met);
}

SS_FN void exact_clip_slab_lanes(float lo, float hi, SDF_FLOAT o, SDF_FLOAT v, SDF_FLOAT* enter, SDF_FLOAT* exit) {
    SDF_FLOAT t0 = (lo - o) / v, t1 = (hi - o) / v;
    *enter = fmax(*enter, fmin(t0, t1));
    *exit = fmin(*exit, fmax(t0, t1));
}
#endif

#endif
