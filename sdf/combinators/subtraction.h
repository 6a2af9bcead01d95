/* Difference of two solids: a minus b. */
#ifndef SDF_COMBINATORS_SUBTRACTION_H
#define SDF_COMBINATORS_SUBTRACTION_H

#include "single_source/vocabulary.h"
#include "sdf/combinators/intersection.h"

/* a intersected with the complement of b: max(a, -b). A bound. Lipschitz bound max(La, Lb)
 * (lipschitz_union): negation keeps a bound. */
SS_FN SDF_FLOAT fOpSubtraction(SDF_FLOAT a, SDF_FLOAT b) { return fOpIntersection(a, -b); }

#endif
