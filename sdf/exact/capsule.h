/* Exact ray intersection of sdf/primitives/capsule.h: the segment from (0, -h, 0) to (0, h, 0)
 * thickened by r. */
#ifndef SDF_EXACT_CAPSULE_H
#define SDF_EXACT_CAPSULE_H

#include "single_source/vocabulary.h"
#include "sdf/exact/cylinder.h"
#include "sdf/exact/interval.h"
#include "sdf/exact/sphere.h"

/* The capsule is convex and the union of the capped cylinder rho <= r, |y| <= h and the spheres of
 * radius r at its ends, so its interval is the union of theirs (exact_union_interval). */
SS_FN float xCapsule(float3 o, float3 v, float r, float half_height, float t_max) {
    float enter = INFINITY, exit = -INFINITY, e0, e1;
    cylinder_interval(o, v, r, half_height, &e0, &e1);
    exact_union_interval(e0, e1, &enter, &exit);
    if (sphere_interval(o - make_float3(0.0f, half_height, 0.0f), v, r, &e0, &e1)) exact_union_interval(e0, e1, &enter, &exit);
    if (sphere_interval(o + make_float3(0.0f, half_height, 0.0f), v, r, &e0, &e1)) exact_union_interval(e0, e1, &enter, &exit);
    return exact_first_crossing(enter, exit, t_max);
}

#ifdef SDF_LANES /* the lane form (sdf/exact/interval.h); a sphere a lane misses gives it an empty interval */
SS_FN SDF_FLOAT xCapsule_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, float half_height,
                               SDF_FLOAT t_max) {
    SDF_FLOAT enter = INFINITY, exit = -INFINITY, e0, e1;
    cylinder_interval_lanes(ox, oy, oz, vx, vy, vz, r, half_height, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    sphere_interval_lanes(ox, oy - half_height, oz, vx, vy, vz, r, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    sphere_interval_lanes(ox, oy + half_height, oz, vx, vy, vz, r, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    return exact_first_crossing_lanes(enter, exit, t_max);
}
#endif

#endif
