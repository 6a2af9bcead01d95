/* Intersection with a 45-degree chamfered convex edge of size r. */
#ifndef SDF_COMBINATORS_INTERSECTION_CHAMFER_H
#define SDF_COMBINATORS_INTERSECTION_CHAMFER_H

#include "single_source/vocabulary.h"
#include "sdf/combinators/union_chamfer.h"

/* -fOpUnionChamfer(-a, -b, r) = max(a, b, (a + b + r) / sqrt 2). Lipschitz bound
 * max(La, Lb, (La + Lb) / sqrt 2) (lipschitz_chamfer). */
SS_FN SDF_FLOAT fOpIntersectionChamfer(SDF_FLOAT a, SDF_FLOAT b, float r) { return -fOpUnionChamfer(-a, -b, r); }

#endif
