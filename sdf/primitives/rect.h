/* A parallelogram without thickness, centred at the origin: the points x U + y V, |x|, |y| <= 1/2
 * (a rect emitter, scene/scene.hpp). It has no inside, so its distance is unsigned; it is never
 * sphere-traced (sdf/exact/rect.h intersects it), the distance only tells which surface a hit point
 * lies on. n is the unit normal U x V / |U x V|; du, dv the dual vectors (V x n, n x U) / |U x V|,
 * so that x = du.p and y = dv.p for a point p of the plane. */
#ifndef SDF_PRIMITIVES_RECT_H
#define SDF_PRIMITIVES_RECT_H

#include "single_source/vocabulary.h"

#ifndef SDF_LANES /* scalar code only: nothing marches it */
/* Distance from q to the segment a + s e, s in [0, 1]. */
SS_FN float rect_segment_distance(float3 q, float3 a, float3 e) {
    float s = clamp(dot(q - a, e) / dot(e, e), 0.0f, 1.0f);
    return length(q - a - e * s);
}

/* Exact unsigned distance: the height above the plane where p projects inside, else the distance
 * to the nearest of the four edges. Lipschitz bound 1. */
SS_FN float fRect_xyz(float px, float py, float pz, float3 u, float3 v, float3 n, float3 du, float3 dv) {
    float3 p = make_float3(px, py, pz);
    float x = dot(p, du), y = dot(p, dv);
    if (fabs(x) <= 0.5f && fabs(y) <= 0.5f) return fabs(dot(p, n));
    float3 c = (u + v) * -0.5f; /* a corner; the edges run c -> c + u -> c + u + v -> c + v -> c */
    float d = fmin(rect_segment_distance(p, c, u), rect_segment_distance(p, c, v));
    return fmin(d, fmin(rect_segment_distance(p, c + u, v), rect_segment_distance(p, c + v, u)));
}

/* The normal of its emitting side (the hit's frame turns it to face the ray where needed). */
SS_FN float3 nRect(float3 n) { return n; }
#endif

#endif
