/* Union with a 45-degree chamfer of size r in the concave crease. */
#ifndef SDF_COMBINATORS_UNION_CHAMFER_H
#define SDF_COMBINATORS_UNION_CHAMFER_H

#include "single_source/vocabulary.h"

/* f = min(a, b, (a + b - r) / sqrt 2): the chamfer is the plane a + b = r in the (a, b) plane, at a
 * right angle that is a flat bevel cutting the crease at distance r (along each operand) from it.
 *
 * Bound: the chamfer term has gradient (grad a + grad b) / sqrt 2, of length at most
 * (La + Lb) / sqrt 2, so f is max(La, Lb, (La + Lb) / sqrt 2)-Lipschitz (lipschitz_chamfer):
 * sqrt 2 for exact operands. It is reached: with parallel gradients (a = x, b = x + c) the chamfer
 * term is the minimum for all x < (r - c) / (2 - sqrt 2), and its slope there is 2 / sqrt 2 = sqrt 2.
 * Only for perpendicular surfaces is it 1 (|grad a + grad b| = sqrt 2). */
SS_FN SDF_FLOAT fOpUnionChamfer(SDF_FLOAT a, SDF_FLOAT b, float r) {
    return fmin(fmin(a, b), (a + b - r) * 0.70710678118654752f);
}

#endif
