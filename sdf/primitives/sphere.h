/* Sphere centred at the origin. */
#ifndef SDF_PRIMITIVES_SPHERE_H
#define SDF_PRIMITIVES_SPHERE_H

#include "single_source/vocabulary.h"

/* Exact signed distance: |p| - r. Lipschitz bound 1.
 * Every distance function has a component form (_xyz: the point as three SDF_FLOATs, one point or a
 * packet of eight; single_source/vocabulary.h), which the scene compiler calls, and a float3 form
 * that calls it. */
SS_FN SDF_FLOAT fSphere_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float r) { return sqrt(x * x + y * y + z * z) - r; }



#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fSphere(float3 p, float r) { return fSphere_xyz(p.x, p.y, p.z, r); }

/* Unit outward normal p / |p|, the gradient of fSphere (undefined at the centre, where every
 * direction is nearest; (0, 1, 0) is returned there). */
SS_FN float3 nSphere(float3 p, float r) {
    (void)r;
    float l = length(p);
    if (!(l > 0.0f)) return make_float3(0.0f, 1.0f, 0.0f);
    return p / l;
}
#endif

#endif
