/* Complex numbers as float2 (x the real part, y the imaginary part), for the wave optics of
 * interfaces with absorbing media (brdf/thin_film.h). */
#ifndef BRDF_COMPLEX_NUMBER_H
#define BRDF_COMPLEX_NUMBER_H
#include "single_source/vocabulary.h"

SS_FN float2 complex_mul(float2 a, float2 b) { return make_float2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

SS_FN float2 complex_div(float2 a, float2 b) {
    float d = b.x * b.x + b.y * b.y;
    return make_float2((a.x * b.x + a.y * b.y) / d, (a.y * b.x - a.x * b.y) / d);
}

/* The principal square root (real part >= 0), from sqrt((|z| + x) / 2), which does not cancel;
 * the other part follows as y / (2 that). */
SS_FN float2 complex_sqrt(float2 z) {
    float m = sqrt(z.x * z.x + z.y * z.y);
    if (m == 0.0f) return make_float2(0.0f, 0.0f);
    if (z.x >= 0.0f) {
        float t = sqrt(0.5f * (m + z.x));
        return make_float2(t, z.y / (2.0f * t));
    }
    float t = sqrt(0.5f * (m - z.x));
    return make_float2(fabs(z.y) / (2.0f * t), z.y < 0.0f ? -t : t);
}

SS_FN float complex_abs(float2 z) { return sqrt(z.x * z.x + z.y * z.y); }

#endif
