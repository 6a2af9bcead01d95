/* Axis-aligned box centred at the origin, half extents half_size (all > 0). */
#ifndef SDF_PRIMITIVES_BOX_H
#define SDF_PRIMITIVES_BOX_H

#include "single_source/vocabulary.h"

/* Exact signed distance. With q = |p| - half_size (per axis), a point outside is nearest to the
 * clamped point, at distance |max(q, 0)|; a point inside is nearest to the face it is closest to,
 * at distance -max_i q_i. The two terms are never both non-zero. Lipschitz bound 1. */
SS_FN SDF_FLOAT fBox_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float hx, float hy, float hz) {
    SDF_FLOAT qx = fabs(x) - hx, qy = fabs(y) - hy, qz = fabs(z) - hz;
    SDF_FLOAT ox = fmax(qx, 0.0f), oy = fmax(qy, 0.0f), oz = fmax(qz, 0.0f);
    return sqrt(ox * ox + oy * oy + oz * oz) + fmin(fmax(qx, fmax(qy, qz)), 0.0f);
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fBox(float3 p, float3 half_size) { return fBox_xyz(p.x, p.y, p.z, half_size.x, half_size.y, half_size.z); }

/* Unit outward normal, the gradient of fBox: outside, the direction from the nearest point of the
 * box (an axis on a face, a diagonal near an edge or corner); inside or on the surface, the normal
 * of the nearest face (ties between faces go to x, then y, then z). */
SS_FN float3 nBox(float3 p, float3 half_size) {
    float3 q = fabs(p) - half_size;
    float3 s = make_float3(p.x < 0.0f ? -1.0f : 1.0f, p.y < 0.0f ? -1.0f : 1.0f, p.z < 0.0f ? -1.0f : 1.0f);
    float3 outside = fmax(q, float3_splat(0.0f));
    float l = length(outside);
    if (l > 0.0f) return s * (outside / l);
    if (q.x >= q.y && q.x >= q.z) return make_float3(s.x, 0.0f, 0.0f);
    if (q.y >= q.z) return make_float3(0.0f, s.y, 0.0f);
    return make_float3(0.0f, 0.0f, s.z);
}
#endif

#endif
