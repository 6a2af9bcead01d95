/* Lipschitz bounds of the combinators, as functions of their operands' bounds, so the scene
 * compiler computes a scene's bound with the same formulas the combinators document.
 * Sphere tracing is safe on a field f with bound L when it steps by |f| / L (Hart 1996): no
 * surface lies closer than |f(p)| / L to p. Exact distances have L = 1; rigid motions, uniform
 * scaling written as s f(p / s), pMirror and (under their conditions) pMod3 / pModInterval3 keep L. */
#ifndef SDF_LIPSCHITZ_H
#define SDF_LIPSCHITZ_H

#include "single_source/vocabulary.h"

/* fOpUnion, fOpIntersection, fOpSubtraction, fOpUnionSmooth: max(la, lb). */
SS_FN float lipschitz_union(float la, float lb) { return fmax(la, lb); }

/* fOpUnionRound, fOpIntersectionRound, fOpSubtractionRound: sqrt(la^2 + lb^2) (sqrt 2 for exact
 * operands); see combinators/union_round.h. */
SS_FN float lipschitz_round(float la, float lb) { return sqrt(la * la + lb * lb); }

/* fOpUnionChamfer, fOpIntersectionChamfer, fOpSubtractionChamfer: max(la, lb, (la + lb) / sqrt 2)
 * (sqrt 2 for exact operands); see combinators/union_chamfer.h. */
SS_FN float lipschitz_chamfer(float la, float lb) { return fmax(fmax(la, lb), (la + lb) * 0.70710678118654752f); }

/* fOpDisplaceSine: ld + |amplitude frequency|; see combinators/displace_sine.h. */
SS_FN float lipschitz_displace_sine(float ld, float amplitude, float frequency) {
    return ld + fabs(amplitude * frequency);
}

#endif
