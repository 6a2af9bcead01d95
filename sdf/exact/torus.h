/* Exact ray intersection of sdf/primitives/torus.h: the circle of radius R in the xz plane thickened
 * by r. */
#ifndef SDF_EXACT_TORUS_H
#define SDF_EXACT_TORUS_H

#include "single_source/vocabulary.h"
#include "sdf/exact/cylinder.h"
#include "sdf/exact/interval.h"

/* How the quartic is solved, and how robust that is.
 *
 * The surface is g = 0 with g(p) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p_x^2 + p_z^2) (g < 0 inside).
 * Along a unit ray p = o + s v it is the monic quartic
 *   g(s) = s^4 + 4 b s^3 + c2 s^2 + c1 s + c0,  b = o.v, c2 = 4 b^2 + 2 k - 4 R^2 |v_xz|^2,
 *   k = |o|^2 + R^2 - r^2.
 * 1. The ray is clipped to the bounding cylinder rho <= R + r, |y| <= r, grown by 1 % of r
 *    (sdf/exact/cylinder.h), and
 *    the origin moved to where it enters it: s then runs over [0, L] with L <= 2 sqrt((R+r)^2 + r^2),
 *    and g's terms are of the torus's size, whatever the ray's distance (no cancellation of huge
 *    terms for a ray from far away; the float error of the moved origin, ~1e-7 of the distance
 *    travelled, is what any float hit point has).
 * 2. The roots are isolated by the derivatives, no root formula: g'' = 12 s^2 + 24 b s + 2 c2 has
 *    closed-form roots, which cut [0, L] into pieces where g' is monotone; each piece holds at most
 *    one root of g', found by a bracketed solve, and those cut [0, L] into pieces where g is
 *    monotone, each holding at most one root of g. The first piece whose ends differ in sign holds
 *    the hit. So no crossing is missed and none is invented; what is lost is a tangent touch (a
 *    double root, where g does not change sign), a set of rays of measure zero.
 * 3. The bracketed solve is Newton's method kept inside its bracket (bisection when a Newton step
 *    would leave it), to a step of 1e-7 (R + r): quadratic convergence on a simple root, never
 *    worse than bisection. The hit is then as precise as g's float evaluation allows, a few ulps of
 *    (R + r) except on grazing rays, where every method's is worse (g' -> 0). */

/* g (derivative 0) or g' (derivative 1) at s, and its own derivative in *slope. */
SS_FN float torus_quartic(float3 o, float3 v, float R, float r, float b, float c2, float s, int derivative, float* slope) {
    float3 p = o + v * s;
    float G = dot(p, p) + R * R - r * r;
    float pv = b + s; /* p.v for a unit v */
    float radial = p.x * v.x + p.z * v.z;
    float g1 = 4.0f * G * pv - 8.0f * R * R * radial;
    if (derivative) {
        *slope = 12.0f * s * s + 24.0f * b * s + 2.0f * c2;
        return g1;
    }
    *slope = g1;
    return G * G - 4.0f * R * R * (p.x * p.x + p.z * p.z);
}

/* The root of g or g' in [s0, s1] where that function is monotone, or -1 when its ends have the
 * same sign (> 0 counts as one sign, <= 0 as the other). */
SS_FN float torus_bracketed_root(float3 o, float3 v, float R, float r, float b, float c2, float s0, float s1, int derivative) {
    float slope;
    float f0 = torus_quartic(o, v, R, r, b, c2, s0, derivative, &slope);
    float f1 = torus_quartic(o, v, R, r, b, c2, s1, derivative, &slope);
    if ((f0 > 0.0f) == (f1 > 0.0f)) return -1.0f;
    bool rising = f1 > 0.0f;
    float tolerance = 1e-7f * (R + r);
    float s = 0.5f * (s0 + s1);
    for (int i = 0; i < 64; ++i) {
        float f = torus_quartic(o, v, R, r, b, c2, s, derivative, &slope);
        if ((f > 0.0f) == rising) s1 = s;
        else s0 = s;
        float next = s - f / slope;
        if (!(next > s0 && next < s1)) next = 0.5f * (s0 + s1);
        float step = fabs(next - s);
        s = next;
        if (step <= tolerance || s1 - s0 <= tolerance) break;
    }
    return s;
}

/* Appends `s` to the sorted cut points cuts[1 .. *count - 1] when it lies strictly inside (0, L). */
SS_FN void torus_add_cut(float s, float L, float cuts[5], int* count) {
    if (s > 0.0f && s < L) cuts[(*count)++] = s;
}

SS_FN float xTorus(float3 o, float3 v, float R, float r, float t_max) {
    float enter, exit;
    /* grown by 1 % of r: the cylinder touches the torus all round its outer equator, and a bracket
     * that started on the surface would not see the sign change there */
    cylinder_interval(o, v, R + 1.01f * r, 1.01f * r, &enter, &exit);
    float lo = fmax(enter, 0.0f), hi = fmin(exit, t_max);
    if (!(lo < hi)) return EXACT_MISS;
    float3 q = o + v * lo;
    float L = hi - lo;
    float b = dot(q, v);
    float k = dot(q, q) + R * R - r * r;
    float c2 = 4.0f * b * b + 2.0f * k - 4.0f * R * R * (v.x * v.x + v.z * v.z);
    /* pieces where g' is monotone: cut at the roots of g'' / 12 = s^2 + 2 b s + c2 / 6 */
    float inflection[5];
    int n_inflection = 1;
    inflection[0] = 0.0f;
    float d = b * b - c2 / 6.0f;
    if (d > 0.0f) {
        float e = sqrt(d);
        torus_add_cut(-b - e, L, inflection, &n_inflection);
        torus_add_cut(-b + e, L, inflection, &n_inflection);
    }
    inflection[n_inflection++] = L;
    /* pieces where g is monotone: cut at the roots of g' */
    float critical[5];
    int n_critical = 1;
    critical[0] = 0.0f;
    for (int i = 0; i + 1 < n_inflection; ++i)
        torus_add_cut(torus_bracketed_root(q, v, R, r, b, c2, inflection[i], inflection[i + 1], 1), L, critical, &n_critical);
    critical[n_critical++] = L;
    for (int i = 0; i + 1 < n_critical; ++i) {
        float s = torus_bracketed_root(q, v, R, r, b, c2, critical[i], critical[i + 1], 0);
        if (s >= 0.0f) {
            float t = lo + s;
            return t > 0.0f && t <= t_max ? t : EXACT_MISS;
        }
    }
    return EXACT_MISS;
}

#endif
