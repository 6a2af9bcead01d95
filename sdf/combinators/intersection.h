/* Intersection of two solids. */
#ifndef SDF_COMBINATORS_INTERSECTION_H
#define SDF_COMBINATORS_INTERSECTION_H

#include "single_source/vocabulary.h"

/* max(a, b). A bound, exact inside when a and b are (outside, near edges the nearest point is on
 * the edge, farther than both). Lipschitz bound max(La, Lb) (lipschitz_union). */
SS_FN SDF_FLOAT fOpIntersection(SDF_FLOAT a, SDF_FLOAT b) { return fmax(a, b); }

#endif
