/* Exact ray intersection of sdf/primitives/box.h: the box |p_i| <= half_size_i. */
#ifndef SDF_EXACT_BOX_H
#define SDF_EXACT_BOX_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The interval in the box: the three slabs' intervals intersected (Kay and Kajiya 1986). */
SS_FN void box_interval(float3 o, float3 v, float3 half_size, float* enter, float* exit) {
    *enter = -INFINITY;
    *exit = INFINITY;
    exact_clip_slab(-half_size.x, half_size.x, o.x, v.x, enter, exit);
    exact_clip_slab(-half_size.y, half_size.y, o.y, v.y, enter, exit);
    exact_clip_slab(-half_size.z, half_size.z, o.z, v.z, enter, exit);
}

SS_FN float xBox(float3 o, float3 v, float3 half_size, float t_max) {
    float enter, exit;
    box_interval(o, v, half_size, &enter, &exit);
    return exact_first_crossing(enter, exit, t_max);
}

#ifdef SDF_LANES /* the lane forms (sdf/exact/interval.h): the same slabs, eight rays at once */
SS_FN void box_interval_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float hx, float hy, float hz,
                              SDF_FLOAT* enter, SDF_FLOAT* exit) {
    *enter = -INFINITY;
    *exit = INFINITY;
    exact_clip_slab_lanes(-hx, hx, ox, vx, enter, exit);
    exact_clip_slab_lanes(-hy, hy, oy, vy, enter, exit);
    exact_clip_slab_lanes(-hz, hz, oz, vz, enter, exit);
}

SS_FN SDF_FLOAT xBox_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float hx, float hy, float hz,
                           SDF_FLOAT t_max) {
    SDF_FLOAT enter, exit;
    box_interval_lanes(ox, oy, oz, vx, vy, vz, hx, hy, hz, &enter, &exit);
    return exact_first_crossing_lanes(enter, exit, t_max);
}
#endif

#endif
