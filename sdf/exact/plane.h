/* Exact ray intersection of sdf/primitives/plane.h: the plane n.p + offset = 0 (n unit). */
#ifndef SDF_EXACT_PLANE_H
#define SDF_EXACT_PLANE_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The one crossing, t = -(n.o + offset) / n.v; none for a ray parallel to the plane (a division by
 * 0 gives an infinity or a NaN, which the range test rejects). */
SS_FN float xPlane(float3 o, float3 v, float3 n, float offset, float t_max) {
    float t = -(dot(n, o) + offset) / dot(n, v);
    return t > 0.0f && t <= t_max ? t : EXACT_MISS;
}

#ifdef SDF_LANES /* the lane form (sdf/exact/interval.h); dot(a, b) is a.x b.x + a.y b.y + a.z b.z */
SS_FN SDF_FLOAT xPlane_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float nx, float ny, float nz,
                             float offset, SDF_FLOAT t_max) {
    SDF_FLOAT t = -((nx * ox + ny * oy + nz * oz) + offset) / (nx * vx + ny * vy + nz * vz);
    return select((SDF_FLOAT)EXACT_MISS, t, t > 0.0f && t <= t_max);
}
#endif

#endif
