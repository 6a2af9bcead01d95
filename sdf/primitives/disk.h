/* A disk without thickness, centred at the origin: radius r in the plane of the unit normal n (a disk
 * emitter, scene/scene.hpp). Unsigned distance, never sphere-traced (sdf/exact/disk.h intersects
 * it): the distance only tells which surface a hit point lies on. */
#ifndef SDF_PRIMITIVES_DISK_H
#define SDF_PRIMITIVES_DISK_H

#include "single_source/vocabulary.h"

#ifndef SDF_LANES /* scalar code only: nothing marches it */
/* Exact unsigned distance: from the height h above the plane and the distance rho from the axis,
 * sqrt(max(rho - r, 0)^2 + h^2). Lipschitz bound 1. */
SS_FN float fDisk_xyz(float px, float py, float pz, float3 n, float r) {
    float3 p = make_float3(px, py, pz);
    float h = dot(p, n);
    float3 radial = p - n * h;
    float out = fmax(length(radial) - r, 0.0f);
    return sqrt(out * out + h * h);
}

/* The normal of its emitting side. */
SS_FN float3 nDisk(float3 n) { return n; }
#endif

#endif
