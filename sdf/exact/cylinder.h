/* Exact ray intersection of sdf/primitives/cylinder.h: the capped cylinder rho <= r, |y| <= h. */
#ifndef SDF_EXACT_CYLINDER_H
#define SDF_EXACT_CYLINDER_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The interval in the capped cylinder: the infinite one's, a t^2 + 2 b t + c <= 0 in the xz
 * components (a = |v_xz|^2), intersected with the slab |y| <= h. The discriminant
 * b^2 - a c = a (r^2 - |o_xz - (b / a) v_xz|^2) comes from the axis's distance to the ray's
 * projection, as the sphere's (sdf/exact/sphere.h). A ray along the axis (a = 0) is inside the
 * infinite cylinder everywhere or nowhere. */
SS_FN void cylinder_interval(float3 o, float3 v, float r, float h, float* enter, float* exit) {
    float a = v.x * v.x + v.z * v.z;
    float c = o.x * o.x + o.z * o.z - r * r;
    *enter = -INFINITY;
    *exit = INFINITY;
    if (a > 0.0f) {
        float b = o.x * v.x + o.z * v.z;
        float s = b / a;
        float fx = o.x - s * v.x, fz = o.z - s * v.z;
        if (!exact_quadratic_roots(a, b, c, a * (r * r - (fx * fx + fz * fz)), enter, exit)) *enter = INFINITY;
    } else if (!(c <= 0.0f)) {
        *enter = INFINITY;
    }
    exact_clip_slab(-h, h, o.y, v.y, enter, exit);
}

SS_FN float xCylinder(float3 o, float3 v, float r, float half_height, float t_max) {
    float enter, exit;
    cylinder_interval(o, v, r, half_height, &enter, &exit);
    return exact_first_crossing(enter, exit, t_max);
}

#ifdef SDF_LANES /* the lane forms (sdf/exact/interval.h): both branches computed, each lane takes its own */
SS_FN void cylinder_interval_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, float h,
                                   SDF_FLOAT* enter, SDF_FLOAT* exit) {
    SDF_FLOAT a = vx * vx + vz * vz;
    SDF_FLOAT c = ox * ox + oz * oz - r * r;
    SDF_FLOAT b = ox * vx + oz * vz;
    SDF_FLOAT s = b / a;
    SDF_FLOAT fx = ox - s * vx, fz = oz - s * vz;
    SDF_FLOAT t0, t1;
    SDF_MASK real = exact_quadratic_roots_lanes(a, b, c, a * (r * r - (fx * fx + fz * fz)), &t0, &t1);
    SDF_MASK tilted = a > 0.0f;
    *enter = select(select((SDF_FLOAT)-INFINITY, (SDF_FLOAT)INFINITY, !(c <= 0.0f)), select((SDF_FLOAT)INFINITY, t0, real), tilted);
    *exit = select((SDF_FLOAT)INFINITY, t1, tilted && real);
    exact_clip_slab_lanes(-h, h, oy, vy, enter, exit);
}

SS_FN SDF_FLOAT xCylinder_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float r, float half_height,
                                SDF_FLOAT t_max) {
    SDF_FLOAT enter, exit;
    cylinder_interval_lanes(ox, oy, oz, vx, vy, vz, r, half_height, &enter, &exit);
    return exact_first_crossing_lanes(enter, exit, t_max);
}
#endif

#endif
