/* Half-space bounded by a plane: the solid is where n.p + offset < 0. */
#ifndef SDF_PRIMITIVES_PLANE_H
#define SDF_PRIMITIVES_PLANE_H

#include "single_source/vocabulary.h"

/* Exact signed distance n.p + offset for a unit normal n (the plane lies at distance -offset from
 * the origin along n; fPlane(p, (0,1,0), 0) is the ground y = 0 with the solid below). Lipschitz
 * bound |n| = 1; a non-unit n scales the field by |n|, so the scene compiler normalises it. */
SS_FN SDF_FLOAT fPlane_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float nx, float ny, float nz, float offset) {
    return x * nx + y * ny + z * nz + offset;
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fPlane(float3 p, float3 n, float offset) { return fPlane_xyz(p.x, p.y, p.z, n.x, n.y, n.z, offset); }

/* Unit outward normal: n itself, everywhere. */
SS_FN float3 nPlane(float3 p, float3 n, float offset) {
    (void)p;
    (void)offset;
    return n;
}
#endif

#endif
