/* Sine displacement of a surface: the example of an operator that breaks 1-Lipschitz. */
#ifndef SDF_COMBINATORS_DISPLACE_SINE_H
#define SDF_COMBINATORS_DISPLACE_SINE_H

#include "single_source/vocabulary.h"

/* d + A sin(w x) sin(w y) sin(w z), with A = amplitude and w = frequency (radians per unit) at the
 * point p where d was evaluated. No longer a distance: the result is a bound only once divided by
 * its Lipschitz constant, which the scene compiler must report (and the marcher divide by).
 *
 * Bound: the gradient of g = A sin(wx) sin(wy) sin(wz) is A w (c1 s2 s3, s1 c2 s3, s1 s2 c3) with
 * s_i, c_i the sines and cosines. With a_i = s_i^2 in [0, 1],
 *   |grad g|^2 / (A w)^2 = a2 a3 + a1 a3 + a1 a2 - 3 a1 a2 a3,
 * which is affine in each a_i, so its maximum over the cube is at a corner: 1 (two a_i = 1, one 0).
 * So |grad g| <= |A w|, reached (e.g. at wx = wz = pi/2, y = 0, where grad g = (0, A w, 0)), and the
 * bound is L_d + |A w| (lipschitz_displace_sine) -- tight when grad d lines up with grad g there,
 * as for a plane y = const. The component-wise estimate L_d + |A w| sqrt 3 is also safe but loose. */
SS_FN SDF_FLOAT fOpDisplaceSine_xyz(SDF_FLOAT d, SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float amplitude, float frequency) {
    return d + amplitude * sin(frequency * x) * sin(frequency * y) * sin(frequency * z);
}
#ifndef SDF_LANES /* scalar code only */
SS_FN float fOpDisplaceSine(float d, float3 p, float amplitude, float frequency) {
    return fOpDisplaceSine_xyz(d, p.x, p.y, p.z, amplitude, frequency);
}
#endif

#endif
