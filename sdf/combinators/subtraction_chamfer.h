/* a minus b with a chamfered edge of size r where b cuts into a. */
#ifndef SDF_COMBINATORS_SUBTRACTION_CHAMFER_H
#define SDF_COMBINATORS_SUBTRACTION_CHAMFER_H

#include "single_source/vocabulary.h"
#include "sdf/combinators/intersection_chamfer.h"

/* fOpIntersectionChamfer(a, -b, r). Lipschitz bound max(La, Lb, (La + Lb) / sqrt 2)
 * (lipschitz_chamfer). */
SS_FN SDF_FLOAT fOpSubtractionChamfer(SDF_FLOAT a, SDF_FLOAT b, float r) { return fOpIntersectionChamfer(a, -b, r); }

#endif
