/* Intersection with a round convex edge of radius r. */
#ifndef SDF_COMBINATORS_INTERSECTION_ROUND_H
#define SDF_COMBINATORS_INTERSECTION_ROUND_H

#include "single_source/vocabulary.h"
#include "sdf/combinators/union_round.h"

/* The complement of the round union of the complements: -fOpUnionRound(-a, -b, r), which is
 * min(-r, max(a, b)) + |(max(r + a, 0), max(r + b, 0))|. Lipschitz bound sqrt(La^2 + Lb^2)
 * (lipschitz_round), reached far outside both solids with parallel gradients. */
SS_FN SDF_FLOAT fOpIntersectionRound(SDF_FLOAT a, SDF_FLOAT b, float r) { return -fOpUnionRound(-a, -b, r); }

#endif
