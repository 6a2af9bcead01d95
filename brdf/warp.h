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
