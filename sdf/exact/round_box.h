/* Exact ray intersection of sdf/primitives/round_box.h: the inner box (half extents
 * half_size - radius) dilated by a ball of the radius. */
#ifndef SDF_EXACT_ROUND_BOX_H
#define SDF_EXACT_ROUND_BOX_H

#include "single_source/vocabulary.h"
#include "sdf/exact/box.h"
#include "sdf/exact/cylinder.h"
#include "sdf/exact/interval.h"
#include "sdf/exact/sphere.h"
#include "sdf/primitives/round_box.h"

/* The dilated box is convex and the union of the inner box grown by the radius along one axis (3
 * boxes), a cylinder of the radius along each of its 12 edges and a ball at each of its 8 corners,
 * so its interval is the union of theirs (exact_union_interval). The outer box holds it all: a ray
 * that misses that box is done after one slab test. */
SS_FN float xRoundBox(float3 o, float3 v, float3 half_size, float radius, float t_max) {
    float e0, e1;
    box_interval(o, v, half_size, &e0, &e1);
    if (!(e0 <= e1)) return EXACT_MISS;
    float r = round_box_radius(half_size.x, half_size.y, half_size.z, radius);
    if (!(r > 0.0f)) return exact_first_crossing(e0, e1, t_max);
    float3 c = half_size - float3_splat(r);
    float enter = INFINITY, exit = -INFINITY;
    box_interval(o, v, make_float3(half_size.x, c.y, c.z), &e0, &e1);
    exact_union_interval(e0, e1, &enter, &exit);
    box_interval(o, v, make_float3(c.x, half_size.y, c.z), &e0, &e1);
    exact_union_interval(e0, e1, &enter, &exit);
    box_interval(o, v, make_float3(c.x, c.y, half_size.z), &e0, &e1);
    exact_union_interval(e0, e1, &enter, &exit);
    for (int i = 0; i < 4; ++i) {
        /* the edges along x, y and z at the four sign pairs of the other two axes; the cylinder's
         * axis is y, so the edge's axis goes to the y component */
        float sa = (i & 1) ? 1.0f : -1.0f, sb = (i & 2) ? 1.0f : -1.0f;
        cylinder_interval(make_float3(o.y - sa * c.y, o.x, o.z - sb * c.z), make_float3(v.y, v.x, v.z), r, c.x, &e0, &e1);
        exact_union_interval(e0, e1, &enter, &exit);
        cylinder_interval(make_float3(o.x - sa * c.x, o.y, o.z - sb * c.z), v, r, c.y, &e0, &e1);
        exact_union_interval(e0, e1, &enter, &exit);
        cylinder_interval(make_float3(o.x - sa * c.x, o.z, o.y - sb * c.y), make_float3(v.x, v.z, v.y), r, c.z, &e0, &e1);
        exact_union_interval(e0, e1, &enter, &exit);
    }
    for (int i = 0; i < 8; ++i) {
        float3 corner = make_float3((i & 1) ? c.x : -c.x, (i & 2) ? c.y : -c.y, (i & 4) ? c.z : -c.z);
        if (sphere_interval(o - corner, v, r, &e0, &e1)) exact_union_interval(e0, e1, &enter, &exit);
    }
    return exact_first_crossing(enter, exit, t_max);
}

#ifdef SDF_LANES /* the lane form (sdf/exact/interval.h): the pieces for every lane unless all miss the outer box */
SS_FN SDF_FLOAT xRoundBox_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float hx, float hy, float hz,
                                float radius, SDF_FLOAT t_max) {
    SDF_FLOAT outer_enter, outer_exit, e0, e1;
    box_interval_lanes(ox, oy, oz, vx, vy, vz, hx, hy, hz, &outer_enter, &outer_exit);
    SDF_MASK outer = outer_enter <= outer_exit;
    if (!SDF_ANY(outer)) return (SDF_FLOAT)EXACT_MISS;
    float r = round_box_radius(hx, hy, hz, radius);
    if (!(r > 0.0f)) return exact_first_crossing_lanes(outer_enter, outer_exit, t_max);
    float cx = hx - r, cy = hy - r, cz = hz - r;
    SDF_FLOAT enter = INFINITY, exit = -INFINITY;
    box_interval_lanes(ox, oy, oz, vx, vy, vz, hx, cy, cz, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    box_interval_lanes(ox, oy, oz, vx, vy, vz, cx, hy, cz, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    box_interval_lanes(ox, oy, oz, vx, vy, vz, cx, cy, hz, &e0, &e1);
    exact_union_interval_lanes(e0, e1, &enter, &exit);
    for (int i = 0; i < 4; ++i) {
        float sa = (i & 1) ? 1.0f : -1.0f, sb = (i & 2) ? 1.0f : -1.0f;
        cylinder_interval_lanes(oy - sa * cy, ox, oz - sb * cz, vy, vx, vz, r, cx, &e0, &e1);
        exact_union_interval_lanes(e0, e1, &enter, &exit);
        cylinder_interval_lanes(ox - sa * cx, oy, oz - sb * cz, vx, vy, vz, r, cy, &e0, &e1);
        exact_union_interval_lanes(e0, e1, &enter, &exit);
        cylinder_interval_lanes(ox - sa * cx, oz, oy - sb * cy, vx, vz, vy, r, cz, &e0, &e1);
        exact_union_interval_lanes(e0, e1, &enter, &exit);
    }
    for (int i = 0; i < 8; ++i) {
        sphere_interval_lanes(ox - ((i & 1) ? cx : -cx), oy - ((i & 2) ? cy : -cy), oz - ((i & 4) ? cz : -cz), vx, vy, vz, r, &e0, &e1);
        exact_union_interval_lanes(e0, e1, &enter, &exit);
    }
    return select((SDF_FLOAT)EXACT_MISS, exact_first_crossing_lanes(enter, exit, t_max), outer);
}
#endif

#endif
