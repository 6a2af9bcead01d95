/* Smooth union (metaballs): the polynomial smooth minimum. */
#ifndef SDF_COMBINATORS_UNION_SMOOTH_H
#define SDF_COMBINATORS_UNION_SMOOTH_H

#include "single_source/vocabulary.h"

/* Quadratic smooth minimum with blend radius k > 0 (k <= 0 is fOpUnion):
 *   h = clamp(1/2 + (b - a) / (2k), 0, 1),   f = b + (a - b) h - k h (1 - h).
 * Where |a - b| >= k it is min(a, b); inside the blend band it lies below min(a, b) by at most k/4
 * (at a = b), so the shapes grow together. It is C1 (the slopes match at h = 0 and h = 1).
 *
 * Bound: inside the band b - a = k (2h - 1) and dh/da = -1/(2k), dh/db = 1/(2k), so
 *   df/da = h + [(a - b) - k (1 - 2h)] dh/da = h,     df/db = 1 - h,
 * because (a - b) = k (1 - 2h): the bracket vanishes. Hence grad f = h grad a + (1 - h) grad b, a
 * CONVEX COMBINATION of the operands' gradients, and |grad f| <= h La + (1 - h) Lb <= max(La, Lb)
 * (lipschitz_union). Outside the band f is a or b. */
SS_FN SDF_FLOAT fOpUnionSmooth(SDF_FLOAT a, SDF_FLOAT b, float k) {
    if (!(k > 0.0f)) return fmin(a, b);
    SDF_FLOAT h = clamp(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
    return mix(b, a, h) - k * h * (1.0f - h);
}

#endif
