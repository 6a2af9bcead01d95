/* Warps from the unit square to directions, with their densities (solid angle measure). */
#ifndef BRDF_WARP_H
#define BRDF_WARP_H
#include "single_source/vocabulary.h"

/* Shirley and Chiu's concentric map from the square to the unit disk, in polar form: area-preserving
 * and with little distortion, so stratified numbers stay stratified (the lens, Malley's method).
 * The angle in units of pi (phi / pi in [-1/4, 3/4]), for cospi and sinpi: their argument needs
 * no reduction by 2 pi, which cos and sin of PoCL make in a call of their own. */
SS_FN void square_to_concentric_disk_polar(float u1, float u2, float* r, float* phi_over_pi) {
    float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    if (a == 0.0f && b == 0.0f) {
        *r = 0.0f;
        *phi_over_pi = 0.0f;
    } else if (fabs(a) > fabs(b)) {
        *r = a;
        *phi_over_pi = 0.25f * (b / a);
    } else {
        *r = b;
        *phi_over_pi = 0.5f - 0.25f * (a / b);
    }
}

/* The same as a point of the unit disk; density 1 / pi over the disk. */
SS_FN float2 square_to_concentric_disk(float u1, float u2) {
    float r, phi_over_pi;
    square_to_concentric_disk_polar(u1, u2, &r, &phi_over_pi);
    return make_float2(r * cospi(phi_over_pi), r * sinpi(phi_over_pi));
}

/* The inverse of square_to_concentric_disk: the point of [0, 1]^2 that maps to (x, y) of the unit
 * disk. In the forward map's first region (|a| > |b|) the point is a (cos phi, sin phi) with
 * phi = pi/4 b/a in (-pi/4, pi/4), so a = sign(x) r and b = a (4/pi) atan(y/x); in the second
 * (|a| <= |b|) it is b (cos phi, sin phi) with phi = pi/2 - pi/4 a/b in [pi/4, 3pi/4], so
 * b = sign(y) r and a = b (2 - (4/pi) phi). The regions meet where |x| = |y|. */
SS_FN float2 concentric_disk_to_square(float x, float y) {
    float r = sqrt(x * x + y * y);
    float a, b;
    if (r == 0.0f) {
        a = 0.0f;
        b = 0.0f;
    } else if (fabs(x) > fabs(y)) {
        a = x > 0.0f ? r : -r;
        b = a * (4.0f * SS_INV_PI) * atan(y / x);
    } else {
        b = y > 0.0f ? r : -r;
        a = b * (2.0f - (4.0f * SS_INV_PI) * atan2(y / b, x / b));
    }
    return make_float2(clamp(0.5f * (a + 1.0f), 0.0f, 1.0f), clamp(0.5f * (b + 1.0f), 0.0f, 1.0f));
}

/* Malley's method: a concentric disk sample lifted onto the hemisphere; pdf = cos(theta) / pi. */
SS_FN float3 square_to_cosine_hemisphere(float u1, float u2) {
    float r, phi_over_pi;
    square_to_concentric_disk_polar(u1, u2, &r, &phi_over_pi);
    /* z from r, not from x and y: 1 - x^2 - y^2 loses the rim to rounding */
    return make_float3(r * cospi(phi_over_pi), r * sinpi(phi_over_pi), safe_sqrt((1.0f - r) * (1.0f + r)));
}

/* A uniform direction on the unit sphere; density 1 / (4 pi). */
SS_FN float3 square_to_uniform_sphere(float u1, float u2) {
    float z = 1.0f - 2.0f * u1;
    float r = safe_sqrt((1.0f - z) * (1.0f + z));
    float phi = 2.0f * SS_PI * u2;
    return make_float3(r * cos(phi), r * sin(phi), z);
}

SS_FN float cosine_hemisphere_pdf(float cos_theta_w) { return fmax(cos_theta_w, 0.0f) * SS_INV_PI; }

#endif
