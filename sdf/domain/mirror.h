/* Mirroring of space about a plane. */
#ifndef SDF_DOMAIN_MIRROR_H
#define SDF_DOMAIN_MIRROR_H

#include "single_source/vocabulary.h"

/* Folds space about the plane n.p + offset = 0 (n unit): a point on the negative side is reflected
 * onto the positive side, so whatever the shape has on the positive side appears mirrored on the
 * negative side (e.g. n = (1, 0, 0), offset = 0 makes a shape symmetric in x).
 * Bound: the fold is 1-Lipschitz (|M(a) - M(b)| <= |a - b|: for points on opposite sides the
 * reflection can only bring them closer), so f(pMirror(p)) is L_f-Lipschitz for ANY shape, and its
 * zero set is what is rendered. It is the exact distance of shape + mirror image when the shape lies
 * on the positive side; a shape that crosses the plane loses its negative-side part. */
SS_FN float3 pMirror(float3 p, float3 n, float offset) {
    float d = dot(p, n) + offset;
    if (d >= 0.0f) return p;
    return p - n * (2.0f * d);
}

#endif
