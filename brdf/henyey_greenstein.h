/* Henyey-Greenstein phase function and the single-scattering subsurface lobe built on it. */
#ifndef BRDF_HENYEY_GREENSTEIN_H
#define BRDF_HENYEY_GREENSTEIN_H
#include "single_source/vocabulary.h"

/* p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)), normalised over the sphere; taken here
 * as a function of 1 - cos, since 1 + g^2 - 2 g cos = (1 - g)^2 + 2 g (1 - cos) does not cancel near
 * the peak when 1 - cos is known accurately. */
SS_FN float henyey_greenstein_phase_of_gap(float one_minus_cos, float g) {
    float denom = sqr(1.0f - g) + 2.0f * g * one_minus_cos;
    return SS_INV_4PI * (1.0f - g * g) / (denom * sqrt(denom));
}

SS_FN float henyey_greenstein_phase(float cos_angle, float g) {
    return henyey_greenstein_phase_of_gap(1.0f - cos_angle, g);
}

/* First-order scattering in a semi-infinite medium of single-scattering albedo 1 (Hanrahan and
 * Krueger 1993, without the boundary's Fresnel terms): f = p(-wi . wo) / (cos_i + cos_o).
 * Light travels along -wi and leaves along wo, so g < 0 scatters back towards the light: the
 * retro-reflection. Reciprocal, and its albedo is at most that of the phase function over the
 * upper hemisphere, since cos_o / (cos_i + cos_o) <= 1. */
SS_FN float henyey_greenstein_subsurface_brdf(float3 wo, float3 wi, float g) {
    float cos_sum = wo.z + wi.z;
    if (!(cos_sum > 0.0f)) return 0.0f;
    /* the phase angle's cosine is -wi.wo, and 1 + wi.wo = |wi + wo|^2 / 2 */
    float3 s = wi + wo;
    return henyey_greenstein_phase_of_gap(0.5f * dot(s, s), g) / cos_sum;
}

#endif
