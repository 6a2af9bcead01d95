/* Union of two solids. */
#ifndef SDF_COMBINATORS_UNION_H
#define SDF_COMBINATORS_UNION_H

#include "single_source/vocabulary.h"

/* min(a, b). Exact outside when a and b are; inside it is a bound (the nearer surface may be
 * buried in the other solid). Lipschitz bound max(La, Lb) (lipschitz_union): the minimum of
 * L-Lipschitz functions is L-Lipschitz. */
SS_FN SDF_FLOAT fOpUnion(SDF_FLOAT a, SDF_FLOAT b) { return fmin(a, b); }

#endif
