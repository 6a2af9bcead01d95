/* Multiple scattering of the rough dielectric (GGX), reflection and transmission, after Kulla and
 * Conty 2017. E_s(mu) is the single-scattering albedo (reflection plus transmission, white) seen from
 * side s (outside, or inside with the inverted index) and E_avg,s its average. The energy a side
 * loses, 1 - E_s(mu_o), is given back by diffuse-like lobes on both sides:
 *   same side:     k_s (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (pi (1 - E_avg,s))
 *   other side:    c   (1 - E_s(mu_o)) (1 - E_s'(mu_i)) / pi
 * Both are symmetric in wo and wi (the transmission is in the lab's flux-conserving form), so the lobe
 * is reciprocal. Their albedos are (1 - E_s(mu_o)) k_s and (1 - E_s(mu_o)) c (1 - E_avg,s'), and
 * k_s = 1 - c (1 - E_avg,s') makes them sum to the loss from either side. c sends the share
 * 1 - F_avg (the average Fresnel transmittance from outside) of the outside's multiple scattering
 * through, bounded so that neither k is negative. */
#ifndef BRDF_DIELECTRIC_COMPENSATION_H
#define BRDF_DIELECTRIC_COMPENSATION_H
#include "single_source/vocabulary.h"
#include "energy_grid.h"
#include "energy_compensation.h"
#include "energy_table_dielectric.h"
#include "frame.h"
#include "microfacet.h"
#include "warp.h"

typedef struct DielectricEnergy {
    float lost_o;   /* 1 - E_s(mu_o): what single scattering loses from wo's side */
    float same;     /* k_s: the share of it reflected back to wo's side */
    float other;    /* c: the coefficient of the lobe on the other side */
    float avg_same, avg_other;  /* E_avg of wo's side and of the other side */
} DielectricEnergy;

/* E_s(mu) or E_avg,s for side 0 (outside) or 1 (inside), GGX of roughness r, index eta. */
SS_FN float dielectric_energy_albedo(int side, float r, float eta, float mu) {
    return energy_grid_ior_albedo(energy_dielectric_albedo + side * DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS * DIELECTRIC_GRID_MU, r, eta, mu);
}

SS_FN float dielectric_energy_average(int side, float r, float eta) {
    return energy_grid_ior_average(energy_dielectric_average + side * DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS, r, eta);
}

SS_FN float dielectric_fresnel_average(float eta) {
    return energy_grid_lerp(energy_dielectric_fresnel_average, DIELECTRIC_GRID_IOR,
                            energy_grid_ior_coordinate(eta));
}

/* The coefficients of the multiple-scattering lobes seen from wo. */
SS_FN DielectricEnergy dielectric_energy(Microfacet mf, float eta, float3 wo) {
    float r = energy_roughness(mf);
    int side = wo.z > 0.0f ? 0 : 1;
    DielectricEnergy d;
    float avg_out = dielectric_energy_average(0, r, eta), avg_in = dielectric_energy_average(1, r, eta);
    float c = fmin((1.0f - dielectric_fresnel_average(eta)) / fmax(1.0f - avg_in, 1e-6f), 1.0f / fmax(1.0f - avg_out, 1e-6f));
    d.avg_same = side == 0 ? avg_out : avg_in;
    d.avg_other = side == 0 ? avg_in : avg_out;
    d.other = c;
    d.same = fmax(1.0f - c * (1.0f - d.avg_other), 0.0f);
    d.lost_o = fmax(1.0f - dielectric_energy_albedo(side, r, eta, fabs(wo.z)), 0.0f);
    return d;
}

/* The multiple-scattering lobes' value for (wo, wi), white. */
SS_FN float dielectric_multiple_scattering_eval(Microfacet mf, float eta, float3 wo, float3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
    DielectricEnergy d = dielectric_energy(mf, eta, wo);
    float r = energy_roughness(mf);
    int side_i = wi.z > 0.0f ? 0 : 1;
    float lost_i = fmax(1.0f - dielectric_energy_albedo(side_i, r, eta, fabs(wi.z)), 0.0f);
    if (same_hemisphere(wo, wi)) return d.avg_same < 1.0f - 1e-6f ? d.same * d.lost_o * lost_i * SS_INV_PI / (1.0f - d.avg_same) : 0.0f;
    return d.other * d.lost_o * lost_i * SS_INV_PI;
}

/* Density of the multiple-scattering lobes' sampler: cosine-weighted on wo's side with probability
 * k_s, on the other side otherwise (their albedo shares). */
SS_FN float dielectric_multiple_scattering_pdf(DielectricEnergy d, float3 wo, float3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
    float share = same_hemisphere(wo, wi) ? d.same : 1.0f - d.same;
    return share * cosine_hemisphere_pdf(fabs(wi.z));
}

/* uc in [0, 1) picks the side, u1 and u2 the direction. */
SS_FN float3 dielectric_multiple_scattering_sample(DielectricEnergy d, float3 wo, float uc, float u1, float u2) {
    float3 wi = square_to_cosine_hemisphere(u1, u2);
    bool up = (uc < d.same) == (wo.z > 0.0f);
    return make_float3(wi.x, wi.y, up ? wi.z : -wi.z);
}

#endif
