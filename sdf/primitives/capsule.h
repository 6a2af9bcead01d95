/* Capsule around the y axis, centred at the origin: the segment from (0, -half_height, 0) to
 * (0, +half_height, 0) thickened by r. half_height is the half length of the straight part; the
 * capsule spans y in [-(half_height + r), half_height + r]. */
#ifndef SDF_PRIMITIVES_CAPSULE_H
#define SDF_PRIMITIVES_CAPSULE_H

#include "single_source/vocabulary.h"

/* p minus its nearest point on the core segment. */
SS_FN SDF_FLOAT capsule_offset_y(SDF_FLOAT y, float half_height) { return y - clamp(y, -half_height, half_height); }

/* Exact signed distance: distance to the core segment minus r. Lipschitz bound 1. */
SS_FN SDF_FLOAT fCapsule_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float r, float half_height) {
    SDF_FLOAT oy = capsule_offset_y(y, half_height);
    return sqrt(x * x + oy * oy + z * z) - r;
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fCapsule(float3 p, float r, float half_height) { return fCapsule_xyz(p.x, p.y, p.z, r, half_height); }

SS_FN float3 capsule_offset(float3 p, float half_height) { return make_float3(p.x, capsule_offset_y(p.y, half_height), p.z); }

/* Unit outward normal: from the nearest point of the segment towards p (undefined on the segment;
 * +x is returned there). */
SS_FN float3 nCapsule(float3 p, float r, float half_height) {
    (void)r;
    float3 v = capsule_offset(p, half_height);
    float l = length(v);
    if (!(l > 0.0f)) return make_float3(1.0f, 0.0f, 0.0f);
    return v / l;
}
#endif

#endif
