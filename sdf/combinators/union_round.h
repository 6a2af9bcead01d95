/* Union with a round fillet of radius r in the concave crease. */
#ifndef SDF_COMBINATORS_UNION_ROUND_H
#define SDF_COMBINATORS_UNION_ROUND_H

#include "single_source/vocabulary.h"

/* With u = (max(r - a, 0), max(r - b, 0)):  f = max(r, min(a, b)) - |u|.
 * Where both a, b >= r it is min(a, b); where one is below r it is that one; where both are below r
 * it is r - |(r - a, r - b)|: the distance from the circle of radius r centred at a = b = r in the
 * (a, b) plane, which is the exact fillet when the two surfaces meet at a right angle.
 *
 * Bound: in the band where both are below r, grad f = ((r - a) grad a + (r - b) grad b) / |u|, and
 * by Cauchy-Schwarz |(r - a) La + (r - b) Lb| <= |u| sqrt(La^2 + Lb^2). So the bound is
 * sqrt(La^2 + Lb^2) (lipschitz_round), sqrt 2 for exact operands, and it is reached: with parallel
 * gradients (two nested or overlapping surfaces facing the same way, e.g. deep inside both solids)
 * |grad f| -> sqrt 2. With exact operands whose gradients make an angle theta it is
 * sqrt(1 + cos theta * 2 (r - a)(r - b) / |u|^2) <= sqrt(1 + max(cos theta, 0)): 1 for
 * perpendicular surfaces (r <= 0 gives max(0, min(a, b)) - |max(-a, -b, 0)|, still this bound). */
SS_FN SDF_FLOAT fOpUnionRound(SDF_FLOAT a, SDF_FLOAT b, float r) {
    SDF_FLOAT ua = fmax(r - a, 0.0f), ub = fmax(r - b, 0.0f);
    return fmax(r, fmin(a, b)) - sqrt(ua * ua + ub * ub);
}

#endif
