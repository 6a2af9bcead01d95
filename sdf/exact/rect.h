/* Exact ray intersection of sdf/primitives/rect.h: the parallelogram x U + y V, |x|, |y| <= 1/2,
 * from either side. */
#ifndef SDF_EXACT_RECT_H
#define SDF_EXACT_RECT_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The plane's crossing t = -n.o / n.v (a parallel ray divides by 0 to an infinity or a NaN, which
 * the tests reject), kept where the point's coordinates x = du.q, y = dv.q lie in [-1/2, 1/2]. */
SS_FN float xRect(float3 o, float3 v, float3 n, float3 du, float3 dv, float t_max) {
    float t = -dot(n, o) / dot(n, v);
    float3 q = o + v * t;
    float x = dot(q, du), y = dot(q, dv);
    return t > 0.0f && t <= t_max && fabs(x) <= 0.5f && fabs(y) <= 0.5f ? t : EXACT_MISS;
}

#ifdef SDF_LANES /* the lane form (sdf/exact/interval.h) */
SS_FN SDF_FLOAT xRect_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float3 n, float3 du, float3 dv,
                            SDF_FLOAT t_max) {
    SDF_FLOAT t = -(n.x * ox + n.y * oy + n.z * oz) / (n.x * vx + n.y * vy + n.z * vz);
    SDF_FLOAT qx = ox + vx * t, qy = oy + vy * t, qz = oz + vz * t;
    SDF_FLOAT x = du.x * qx + du.y * qy + du.z * qz, y = dv.x * qx + dv.y * qy + dv.z * qz;
    return select((SDF_FLOAT)EXACT_MISS, t, t > 0.0f && t <= t_max && fabs(x) <= 0.5f && fabs(y) <= 0.5f);
}
#endif

#endif
