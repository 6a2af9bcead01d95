/* Warps from the unit square to directions, with their densities (solid angle measure). */
#ifndef BRDF_WARP_H
#define BRDF_WARP_H
#include "single_source/vocabulary.h"

/* Malley's method: a concentric disk sample lifted onto the hemisphere; pdf = cos(theta) / pi. */
SS_FN float3 square_to_cosine_hemisphere(float u1, float u2) {
    float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    float r, phi;
    if (a == 0.0f && b == 0.0f) {
        r = 0.0f;
        phi = 0.0f;
    } else if (fabs(a) > fabs(b)) {
        r = a;
        phi = (SS_PI / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (SS_PI / 2.0f) - (SS_PI / 4.0f) * (a / b);
    }
    /* z from r, not from x and y: 1 - x^2 - y^2 loses the rim to rounding */
    return make_float3(r * cos(phi), r * sin(phi), safe_sqrt((1.0f - r) * (1.0f + r)));
}

SS_FN float cosine_hemisphere_pdf(float cos_theta_w) { return fmax(cos_theta_w, 0.0f) * SS_INV_PI; }

#endif
