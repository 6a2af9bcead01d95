/* Sphere centred at the origin. */
#ifndef SDF_PRIMITIVES_SPHERE_H
#define SDF_PRIMITIVES_SPHERE_H

#include "single_source/vocabulary.h"

/* Exact signed distance: |p| - r. Lipschitz bound 1. */
SS_FN float fSphere(float3 p, float r) { return length(p) - r; }

/* Unit outward normal p / |p|, the gradient of fSphere (undefined at the centre, where every
 * direction is nearest; (0, 1, 0) is returned there). */
SS_FN float3 nSphere(float3 p, float r) {
    (void)r;
    float l = length(p);
    if (!(l > 0.0f)) return make_float3(0.0f, 1.0f, 0.0f);
    return p / l;
}

#endif
