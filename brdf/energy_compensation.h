/* Multiple scattering between microfacets, in the form of Kulla and Conty 2017 ("Revisiting
 * physically based shading at Imageworks"): the energy 1 - E(mu_o) that single scattering loses is
 * given back by a diffuse-like lobe
 *   f_ms(wo, wi) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),   E_avg = 2 int E(mu) mu dmu,
 * whose directional albedo is exactly 1 - E(mu_o), times the colour of the light that escapes after
 * two or more bounces, each absorbing 1 - F_avg:
 *   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),   F_avg = 2 int F(mu) mu dmu = F0 + (1 - F0) / 21 (Schlick).
 * f_ms is symmetric in wo and wi, so the compensated lobe stays reciprocal. E and E_avg come from
 * tables (brdf/energy_grid.h) over roughness and shape; an anisotropic distribution uses the
 * isotropic one of the same alpha_x alpha_y. */
#ifndef BRDF_ENERGY_COMPENSATION_H
#define BRDF_ENERGY_COMPENSATION_H
#include "single_source/vocabulary.h"
#include "energy_grid.h"
#include "features.h"
#include "microfacet.h"
#if BRDF_FEATURE_GGX
#include "energy_table_ggx.h"
#endif
#if BRDF_FEATURE_HYPER_CAUCHY
#include "energy_table_hyper_cauchy.h"
#endif

typedef struct MicrofacetEnergy {
    float albedo_o;  /* E(mu_o) */
    float average;   /* E_avg */
} MicrofacetEnergy;

/* The perceptual roughness of the isotropic distribution of alpha = sqrt(alpha_x alpha_y). */
SS_FN float energy_roughness(Microfacet mf) { return sqrt(sqrt(mf.ax * mf.ay)); }

/* The Hyper-Cauchy shape slice below g, and the weight of the one above. */
SS_FN int energy_shape_slice(float g, float* weight) {
    float s = energy_grid_shape_coordinate(g);
    int k = min((int)s, ENERGY_GRID_SHAPE - 2);
    *weight = s - (float)k;
    return k;
}

/* E at mu of the distribution of normals mf, and its average. */
SS_FN float microfacet_energy_albedo(Microfacet mf, float mu) {
    float r = energy_roughness(mf);
#if BRDF_FEATURE_HYPER_CAUCHY
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY) {
        float t;
        CONSTANT_MEM const ushort* slice = energy_hyper_cauchy_albedo + energy_shape_slice(mf.shape, &t) * ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU;
        return mix(energy_table_albedo(slice, r, mu), energy_table_albedo(slice + ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU, r, mu), t);
    }
#endif
#if BRDF_FEATURE_GGX
    return energy_table_albedo(energy_ggx_albedo, r, mu);
#else
    return 1.0f;
#endif
}

SS_FN float microfacet_energy_average(Microfacet mf) {
    float x = energy_grid_roughness_coordinate(energy_roughness(mf));
#if BRDF_FEATURE_HYPER_CAUCHY
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY) {
        float t;
        CONSTANT_MEM const float* row = energy_hyper_cauchy_average + energy_shape_slice(mf.shape, &t) * ENERGY_GRID_ROUGHNESS;
        return mix(energy_grid_lerp(row, ENERGY_GRID_ROUGHNESS, x), energy_grid_lerp(row + ENERGY_GRID_ROUGHNESS, ENERGY_GRID_ROUGHNESS, x), t);
    }
#endif
#if BRDF_FEATURE_GGX
    return energy_grid_lerp(energy_ggx_average, ENERGY_GRID_ROUGHNESS, x);
#else
    return 1.0f;
#endif
}

/* F_ms: the colour of multiply scattered light for Schlick's Fresnel of normal reflectance f0. */
SS_FN float3 multiple_scattering_fresnel(float3 f0, float e_avg) {
    float3 f_avg = f0 + (float3_splat(1.0f) - f0) * (1.0f / 21.0f);
    return f_avg * f_avg * e_avg / (float3_splat(1.0f) - f_avg * (1.0f - e_avg));
}

/* f_ms(wo, wi) without its colour, for wo and wi on the upper side. */
SS_FN float multiple_scattering_eval(Microfacet mf, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float e_avg = microfacet_energy_average(mf);
    if (!(e_avg < 1.0f - 1e-6f)) return 0.0f;
    float lost_o = fmax(1.0f - microfacet_energy_albedo(mf, wo.z), 0.0f);
    float lost_i = fmax(1.0f - microfacet_energy_albedo(mf, wi.z), 0.0f);
    return lost_o * lost_i * SS_INV_PI / (1.0f - e_avg);
}

/* Directional albedo of f_ms (without its colour): 1 - E(mu_o), where E_avg < 1. */
SS_FN float multiple_scattering_albedo(Microfacet mf, float mu_o) {
    if (!(mu_o > 0.0f) || !(microfacet_energy_average(mf) < 1.0f - 1e-6f)) return 0.0f;
    return fmax(1.0f - microfacet_energy_albedo(mf, mu_o), 0.0f);
}

#endif
