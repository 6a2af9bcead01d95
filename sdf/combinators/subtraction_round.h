/* a minus b with a round edge of radius r where b cuts into a. */
#ifndef SDF_COMBINATORS_SUBTRACTION_ROUND_H
#define SDF_COMBINATORS_SUBTRACTION_ROUND_H

#include "single_source/vocabulary.h"
#include "sdf/combinators/intersection_round.h"

/* fOpIntersectionRound(a, -b, r). Lipschitz bound sqrt(La^2 + Lb^2) (lipschitz_round). */
SS_FN SDF_FLOAT fOpSubtractionRound(SDF_FLOAT a, SDF_FLOAT b, float r) { return fOpIntersectionRound(a, -b, r); }

#endif
