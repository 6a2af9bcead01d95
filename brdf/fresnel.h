/* Fresnel terms. */
#ifndef BRDF_FRESNEL_H
#define BRDF_FRESNEL_H
#include "single_source/vocabulary.h"

/* Schlick's weight (1 - cos)^5: how far a reflectance moves from its normal value towards 1. */
SS_FN float schlick_weight(float cos_angle) { return pow5(clamp(1.0f - cos_angle, 0.0f, 1.0f)); }

/* Schlick 1994: F = F0 + (1 - F0) (1 - cos)^5, per channel. */
SS_FN float3 fresnel_schlick(float3 f0, float cos_angle) {
    return f0 + (float3_splat(1.0f) - f0) * schlick_weight(cos_angle);
}

/* OpenPBR 1.1's metal Fresnel, the F82-tint model (Hoffman 2023, "Generalization of Adobe's Fresnel
 * model", in the notation of Kutz et al. 2021): Schlick's curve less a term b mu (1 - mu)^6 that is
 * zero at normal and grazing incidence and pulls the curve at mu_bar = 1/7 (about 82 degrees) down
 * to tint times Schlick's value there:
 *   F82(mu) = F_Schlick(mu) - b mu (1 - mu)^6,  b = F_Schlick(mu_bar) (1 - tint) / (mu_bar (1 - mu_bar)^6).
 * A white tint gives b = 0 and Schlick's curve exactly. The formula dips below zero for a dark F0
 * with a dark tint (F0 = 0, tint = 0: -0.033 at 60 degrees), hence the floor at 0; it never exceeds
 * Schlick's value, so it stays at most 1. */
SS_FN float3 fresnel_f82_tint(float3 f0, float3 tint, float cos_angle) {
    const float mu_bar = 1.0f / 7.0f;
    float mu = clamp(cos_angle, 0.0f, 1.0f);
    float3 b = fresnel_schlick(f0, mu_bar) * (float3_splat(1.0f) - tint) / (mu_bar * (1.0f - mu_bar) * schlick_weight(mu_bar));
    float3 f = fresnel_schlick(f0, mu) - b * (mu * (1.0f - mu) * schlick_weight(mu));
    return fmax(f, float3_splat(0.0f));
}

/* Normal-incidence reflectance with metallic (Burley 2012): dielectrics reflect `fresnel` grey,
 * conductors reflect their albedo. */
SS_FN float3 specular_f0(float3 albedo, float fresnel, float metallic) {
    return mix(float3_splat(fresnel), albedo, metallic);
}

/* Fresnel's amplitude reflection coefficient (a cos_i - b cos_t) / (a cos_i + b cos_t) of an
 * interface from index n_i into n_t: s-polarised with a = n_i, b = n_t; p-polarised with a = n_t,
 * b = n_i. */
SS_FN float fresnel_amplitude(float a, float b, float cos_i, float cos_t) {
    return (a * cos_i - b * cos_t) / (a * cos_i + b * cos_t);
}

/* Exact unpolarised Fresnel reflectance of a dielectric interface. cos_i is measured on the side
 * of the normal (negative: from inside); eta = eta_inside / eta_outside. */
SS_FN float fresnel_dielectric(float cos_i, float eta) {
    if (eta == 1.0f) return 0.0f; /* index matched; below, 1 - cos^2 would round to 1 at grazing */
    cos_i = clamp(cos_i, -1.0f, 1.0f);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
    }
    float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    float cos_t = safe_sqrt(1.0f - sin2_t);
    float r_parallel = fresnel_amplitude(eta, 1.0f, cos_i, cos_t);
    float r_perpendicular = fresnel_amplitude(1.0f, eta, cos_i, cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

#endif
