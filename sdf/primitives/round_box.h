/* Box with rounded edges and corners, centred at the origin. half_size is the OUTER half extent
 * (the rounded box fits exactly in the box fBox(p, half_size)); radius is the rounding radius,
 * 0 <= radius <= min(half_size). */
#ifndef SDF_PRIMITIVES_ROUND_BOX_H
#define SDF_PRIMITIVES_ROUND_BOX_H

#include "single_source/vocabulary.h"
#include "sdf/primitives/box.h"

/* The inner box, shrunk by the radius on every side; the radius is capped at the smallest half
 * extent so the inner box never turns inside out (the scene compiler should reject such a radius). */
SS_FN float round_box_radius(float hx, float hy, float hz, float radius) { return fmin(radius, fmin(hx, fmin(hy, hz))); }

/* The rounded box is the inner box B dilated by a ball of the radius (Minkowski sum). For a convex
 * B the signed distance of its dilation is d_B - radius everywhere: outside, following the gradient
 * of d_B raises it at rate 1 and no path can do better (d_B is 1-Lipschitz); inside, the same
 * argument reversed. So this is exact, Lipschitz bound 1. */
SS_FN SDF_FLOAT fRoundBox_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float hx, float hy, float hz, float radius) {
    float r = round_box_radius(hx, hy, hz, radius);
    return fBox_xyz(x, y, z, hx - r, hy - r, hz - r) - r;
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fRoundBox(float3 p, float3 half_size, float radius) {
    return fRoundBox_xyz(p.x, p.y, p.z, half_size.x, half_size.y, half_size.z, radius);
}

SS_FN float3 round_box_core(float3 half_size, float radius) {
    return half_size - float3_splat(round_box_radius(half_size.x, half_size.y, half_size.z, radius));
}

/* Unit outward normal: the gradient of the inner box's distance (a constant offset keeps it). */
SS_FN float3 nRoundBox(float3 p, float3 half_size, float radius) { return nBox(p, round_box_core(half_size, radius)); }
#endif

#endif
