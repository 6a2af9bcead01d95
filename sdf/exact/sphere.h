/* Exact ray intersection of sdf/primitives/sphere.h: the sphere |p| = r. */
#ifndef SDF_EXACT_SPHERE_H
#define SDF_EXACT_SPHERE_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The interval of t where |o + t v| <= r (v unit): t^2 + 2 b t + c <= 0 with b = o.v and
 * c = |o|^2 - r^2. The discriminant b^2 - c = r^2 - |o - b v|^2 is taken from the distance of the
 * centre to the line (Haines et al. 2019), exact where b^2 - c would cancel (far or grazing rays). */
SS_FN int sphere_interval(float3 o, float3 v, float r, float* enter, float* exit) {
    float b = dot(o, v);
    float3 f = o - v * b;
    return exact_quadratic_roots(1.0f, b, dot(o, o) - r * r, r * r - dot(f, f), enter, exit);
}

SS_FN float xSphere(float3 o, float3 v, float r, float t_max) {
    float enter, exit;
    if (!sphere_interval(o, v, r, &enter, &exit)) return EXACT_MISS;
    return exact_first_crossing(enter, exit, t_max);
}

#ifdef SDF_LANES /* the lane forms (sdf/exact/interval.h); dot(a, b) is a.x b.x + a.y b.y + a.z b.z */
/* Where a lane has no real root, its interval is the empty [INFINITY, -INFINITY] (the scalar form
 * leaves it unset and says 0), which a union skips and a first crossing misses. */
SS_FN void sphere_interval_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, SDF_FLOAT* enter,
                                 SDF_FLOAT* exit) {
    SDF_FLOAT b = ox * vx + oy * vy + oz * vz;
    SDF_FLOAT fx = ox - vx * b, fy = oy - vy * b, fz = oz - vz * b;
    SDF_MASK real = exact_quadratic_roots_lanes((SDF_FLOAT)1.0f, b, (ox * ox + oy * oy + oz * oz) - r * r, r * r - (fx * fx + fy * fy + fz * fz),
                                                enter, exit);
    *enter = select((SDF_FLOAT)INFINITY, *enter, real);
    *exit = select((SDF_FLOAT)-INFINITY, *exit, real);
}

SS_FN SDF_FLOAT xSphere_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, SDF_FLOAT t_max) {
    SDF_FLOAT enter, exit;
    sphere_interval_lanes(ox, oy, oz, vx, vy, vz, r, &enter, &exit);
    return exact_first_crossing_lanes(enter, exit, t_max);
}
#endif

#endif
