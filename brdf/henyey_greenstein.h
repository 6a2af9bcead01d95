/* Henyey-Greenstein phase function and the single-scattering subsurface lobe built on it. */
#ifndef BRDF_HENYEY_GREENSTEIN_H
#define BRDF_HENYEY_GREENSTEIN_H
#include "single_source/vocabulary.h"
#include "frame.h"

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

/* Direction whose angle to `axis` follows the phase function of asymmetry g: the closed-form
 * inverse of the CDF of cos (Henyey and Greenstein 1941), phi uniform. */
SS_FN float3 henyey_greenstein_sample(float3 axis, float g, float u1, float u2) {
    float cos_angle;
    if (fabs(g) < 1e-3f) {
        cos_angle = 1.0f - 2.0f * u1;
    } else {
        float q = (1.0f - g * g) / (1.0f + g - 2.0f * g * u1);
        cos_angle = clamp((1.0f + g * g - q * q) / (2.0f * g), -1.0f, 1.0f);
    }
    float sin_angle = safe_sqrt(1.0f - cos_angle * cos_angle), phi = 2.0f * SS_PI * u2;
    ShadingFrame f = frame_from_normal(axis);
    return frame_to_world(f, make_float3(sin_angle * cos(phi), sin_angle * sin(phi), cos_angle));
}

/* The subsurface lobe's sampler: wi about -wo with the phase function (the lobe's numerator), a
 * direction below the surface mirrored to the upper side. Its density is the phase function at wi
 * plus at wi's mirror image, so the weight f cos_i / pdf stays below cos_i / (cos_i + cos_o) <= 1. */
SS_FN float3 henyey_greenstein_subsurface_sample(float3 wo, float g, float u1, float u2) {
    float3 wi = henyey_greenstein_sample(-wo, g, u1, u2);
    return make_float3(wi.x, wi.y, fabs(wi.z));
}

SS_FN float henyey_greenstein_subsurface_pdf(float3 wo, float3 wi, float g) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float3 s = wi + wo;
    float3 mirrored = make_float3(s.x, s.y, wo.z - wi.z);
    return henyey_greenstein_phase_of_gap(0.5f * dot(s, s), g) + henyey_greenstein_phase_of_gap(0.5f * dot(mirrored, mirrored), g);
}

#endif
