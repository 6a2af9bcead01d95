/* The energy-preserving Oren-Nayar diffuse lobe (EON: Portsmouth, Kutz and Hill 2025, "EON: A
 * practical energy-preserving rough diffuse BRDF", JCGT 14(1)), OpenPBR 1.1's rough diffuse for
 * base_diffuse_roughness. Directions in the local frame, both above the horizon; rho the albedo,
 * sigma the roughness in [0, 1]. */
#ifndef BRDF_EON_DIFFUSE_H
#define BRDF_EON_DIFFUSE_H
#include "single_source/vocabulary.h"
#include "warp.h"

/* The paper's constants: c1 = 1/2 - 2/(3 pi) sets Fujii's A = 1 / (1 + c1 sigma), so that a white
 * lobe reflects everything at grazing view; c2 = 2/3 - 28/(15 pi) gives the average albedo
 * E_avg = A + B c2 = 2 integral of E(mu) mu dmu. */
#define EON_C1 (0.5f - 2.0f / (3.0f * SS_PI))
#define EON_C2 (2.0f / 3.0f - 28.0f / (15.0f * SS_PI))

/* G(mu) of the paper's exact directional albedo E(mu) = A + (B / pi) G(mu) of Fujii's lobe:
 * G = sin t (t - sin t cos t) + (2/3) tan t (1 - sin^3 t) - (2/3) sin t, t = acos(mu), with
 * tan t (1 - sin^3 t) written as sin t cos t (1 + sin t + sin^2 t) / (1 + sin t), which has no
 * 0/0 at grazing. G rises from 0 at mu = 1 to c1 pi at mu = 0. */
SS_FN float eon_albedo_g(float mu) {
    mu = clamp(mu, 0.0f, 1.0f);
    float s = safe_sqrt(1.0f - mu * mu), t = acos(mu);
    return s * (t - s * mu) + (2.0f / 3.0f) * (s * mu * (1.0f + s + s * s) / (1.0f + s) - s);
}

/* c1 - G(mu) / pi, the part of Fujii's albedo lost at mu: 1 - E(mu) = A sigma (c1 - G(mu) / pi). */
SS_FN float eon_albedo_loss(float mu) { return fmax(EON_C1 - eon_albedo_g(mu) * SS_INV_PI, 0.0f); }

/* Fujii's Oren-Nayar (the paper's f_FON, single scattering):
 * f = (rho / pi) (A + B s / t), A = 1 / (1 + c1 sigma), B = sigma A, s = wi.wo - mu_i mu_o,
 * t = max(mu_i, mu_o) where s > 0, else 1. Symmetric in wo and wi; A = 1, B = 0 at sigma = 0. */
SS_FN float3 eon_single_scattering_brdf(float3 rho, float sigma, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return float3_splat(0.0f);
    float a = 1.0f / (1.0f + EON_C1 * sigma), b = sigma * a;
    float s = dot(wi, wo) - wi.z * wo.z;
    float s_over_t = s > 0.0f ? s / fmax(wi.z, wo.z) : s;
    return rho * (SS_INV_PI * (a + b * s_over_t));
}

/* The paper's analytic compensation (Kulla-Conty form over Fujii's exact albedo):
 * f_ms = (rho_ms / pi) (1 - E(mu_o)) (1 - E(mu_i)) / (1 - E_avg),
 * rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)). With 1 - E = A sigma (c1 - G / pi) and
 * 1 - E_avg = A sigma (c1 - c2) one factor A sigma cancels, so sigma = 0 gives 0, not 0/0.
 * Its albedo at mu_o is rho_ms (1 - E(mu_o)): a white lobe's total is exactly 1. */
SS_FN float3 eon_multiple_scattering_brdf(float3 rho, float sigma, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return float3_splat(0.0f);
    float a = 1.0f / (1.0f + EON_C1 * sigma);
    float e_avg = a + sigma * a * EON_C2;
    float3 rho_ms = rho * rho * e_avg / (float3_splat(1.0f) - rho * (1.0f - e_avg));
    float shape = a * sigma * eon_albedo_loss(wo.z) * eon_albedo_loss(wi.z) / (EON_C1 - EON_C2);
    return rho_ms * (SS_INV_PI * shape);
}

SS_FN float3 eon_brdf(float3 rho, float sigma, float3 wo, float3 wi) {
    return eon_single_scattering_brdf(rho, sigma, wo, wi) + eon_multiple_scattering_brdf(rho, sigma, wo, wi);
}

/* Sampling: cosine-weighted (Malley), not the paper's clipped linearly transformed cosines (a fitted
 * LTC that follows the lobe's backscatter). Exact and cheap; its weight f cos / pdf = pi f
 * grows without bound only towards backscatter with both directions near grazing, where s / t grows
 * as 1 / max(mu_i, mu_o). */
SS_FN float3 eon_sample(float u1, float u2) { return square_to_cosine_hemisphere(u1, u2); }

SS_FN float eon_pdf(float3 wo, float3 wi) { return wo.z > 0.0f ? cosine_hemisphere_pdf(wi.z) : 0.0f; }

#endif
