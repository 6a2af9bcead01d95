/* Multiple scattering between microfacets, in the form of Kulla and Conty 2017 ("Revisiting
 * physically based shading at Imageworks"): the energy 1 - E(mu_o) that single scattering loses is
 * given back by a diffuse-like lobe
 *   f_ms(wo, wi) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),   E_avg = 2 int E(mu) mu dmu,
 * whose directional albedo is exactly 1 - E(mu_o), times the colour of the light that escapes after
 * two or more bounces, each absorbing 1 - F_avg:
 *   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),   F_avg = 2 int F(mu) mu dmu = F0 + (1 - F0) / 21 (Schlick).
 * f_ms is symmetric in wo and wi, so the compensated lobe stays reciprocal. E and E_avg come from
 * tables (brdf/energy_grid.h) over roughness and shape. An anisotropic GGX distribution's E depends
 * on the azimuth of w too, and no isotropic roughness matches it (docs/materials.md gives the figures):
 * its E(w) comes from a table over the ratio alpha_y / alpha_x, that azimuth, roughness and mu, and
 * E_avg from the same table's hemispherical average. That table is too large for __constant memory:
 * it is read from the BSDF's tables in global memory (`tables`, brdf/bsdf_tables.h), which kernels
 * receive as a buffer argument. An anisotropic Hyper-Cauchy one uses the isotropic table of the same
 * alpha_x alpha_y. */
#ifndef BRDF_ENERGY_COMPENSATION_H
#define BRDF_ENERGY_COMPENSATION_H
#include "single_source/vocabulary.h"
#include "energy_grid.h"
#include "features.h"
#include "microfacet.h"
#if BRDF_FEATURE_GGX
#include "energy_table_ggx.h"
#endif
#include "bsdf_tables.h"
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

#if BRDF_FEATURE_GGX
/* Whether mf takes the anisotropic table. */
SS_FN bool energy_is_anisotropic(Microfacet mf) { return mf.kind == BRDF_DISTRIBUTION_GGX && mf.ax != mf.ay; }

/* The fractional ratio and roughness node coordinates of mf (alpha_x >= alpha_y after the swap). */
SS_FN float2 energy_anisotropic_coordinates(float ax, float ay) {
    float q = ay / ax, r = sqrt(sqrt(0.5f * (ax * ax + ay * ay)));
    return make_float2(anisotropic_grid_ratio_coordinate(q),
                       energy_grid_node_coordinate(r, 0.0f, ANISO_GRID_ROUGHNESS_MAX, ANISO_GRID_ROUGHNESS));
}

/* atan2(y, x) for x, y >= 0 in basic arithmetic (Abramowitz and Stegun 4.4.49, within 1e-5 rad), so
 * the C++ and OpenCL builds round it alike, as their atan2 do not; 0 at the pole, where E is the same
 * at every phi. */
SS_FN float energy_azimuth(float x, float y) {
    if (!(x > 0.0f || y > 0.0f)) return 0.0f;
    float t = fmin(x, y) / fmax(x, y), t2 = t * t;
    float a = t * (0.9998660f + t2 * (-0.3302995f + t2 * (0.1801410f + t2 * (-0.0851330f + t2 * 0.0208351f))));
    return y > x ? 0.5f * SS_PI - a : a;
}

/* E(w) of an anisotropic GGX distribution: the table interpolated in ratio, azimuth, roughness and mu,
 * as 1 - E (energy_grid_lerp_lost says why). */
SS_FN float energy_anisotropic_albedo(Microfacet mf, GLOBAL_MEM const float* tables, float3 w) {
    float ax = mf.ax, ay = mf.ay, wx = fabs(w.x), wy = fabs(w.y);
    if (ay > ax) {
        ax = mf.ay, ay = mf.ax, wx = fabs(w.y), wy = fabs(w.x);
    }
    float2 c = energy_anisotropic_coordinates(ax, ay);
    float p = anisotropic_grid_phi_coordinate(energy_azimuth(wx, wy));
    float m = energy_grid_mu_coordinate_of(w.z, ANISO_GRID_MU);
    int k = min((int)c.x, ANISO_GRID_RATIO - 2), l = min((int)p, ANISO_GRID_PHI - 2), i = min((int)c.y, ANISO_GRID_ROUGHNESS - 2);
    float tk = c.x - (float)k, tl = p - (float)l, ti = c.y - (float)i, lost = 0.0f;
    for (int dk = 0; dk < 2; ++dk)
        for (int dl = 0; dl < 2; ++dl)
            for (int di = 0; di < 2; ++di) {
                float weight = (dk ? tk : 1.0f - tk) * (dl ? tl : 1.0f - tl) * (di ? ti : 1.0f - ti);
                int row = (((k + dk) * ANISO_GRID_PHI + l + dl) * ANISO_GRID_ROUGHNESS + i + di) * ANISO_GRID_MU;
                lost += weight * energy_grid_lerp_lost(bsdf_tables_anisotropic_albedo(tables) + row, ANISO_GRID_MU, m);
            }
    return 1.0f - lost;
}

/* E_avg of an anisotropic GGX distribution, interpolated in ratio and roughness like E above, so that
 * it is the hemispherical average of the interpolated E(w) (the generator averages over the azimuth
 * the interpolant, linear in phi between its nodes). */
SS_FN float energy_anisotropic_average(Microfacet mf, GLOBAL_MEM const float* tables) {
    float2 c = energy_anisotropic_coordinates(fmax(mf.ax, mf.ay), fmin(mf.ax, mf.ay));
    int k = min((int)c.x, ANISO_GRID_RATIO - 2), i = min((int)c.y, ANISO_GRID_ROUGHNESS - 2);
    GLOBAL_MEM const float* row = tables + BSDF_TABLES_ANISOTROPIC_AVERAGE + k * ANISO_GRID_ROUGHNESS + i;
    float t = c.y - (float)i;
    return mix(mix(row[0], row[1], t), mix(row[ANISO_GRID_ROUGHNESS], row[ANISO_GRID_ROUGHNESS + 1], t), c.x - (float)k);
}
#endif

/* E at w (upper side) of the distribution of normals mf, and its average. */
SS_FN float microfacet_energy_albedo(Microfacet mf, GLOBAL_MEM const float* tables, float3 w) {
    float mu = w.z;
#if BRDF_FEATURE_GGX
    if (energy_is_anisotropic(mf)) return energy_anisotropic_albedo(mf, tables, w);
#endif
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

SS_FN float microfacet_energy_average(Microfacet mf, GLOBAL_MEM const float* tables) {
#if BRDF_FEATURE_GGX
    if (energy_is_anisotropic(mf)) return energy_anisotropic_average(mf, tables);
#endif
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
SS_FN float multiple_scattering_eval(Microfacet mf, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float e_avg = microfacet_energy_average(mf, tables);
    if (!(e_avg < 1.0f - 1e-6f)) return 0.0f;
    float lost_o = fmax(1.0f - microfacet_energy_albedo(mf, tables, wo), 0.0f);
    float lost_i = fmax(1.0f - microfacet_energy_albedo(mf, tables, wi), 0.0f);
    return lost_o * lost_i * SS_INV_PI / (1.0f - e_avg);
}

/* Directional albedo of f_ms (without its colour): 1 - E(wo), where E_avg < 1. */
SS_FN float multiple_scattering_albedo(Microfacet mf, GLOBAL_MEM const float* tables, float3 wo) {
    if (!(wo.z > 0.0f) || !(microfacet_energy_average(mf, tables) < 1.0f - 1e-6f)) return 0.0f;
    return fmax(1.0f - microfacet_energy_albedo(mf, tables, wo), 0.0f);
}

#ifndef __OPENCL_C_VERSION__
/* On the host, E and E_avg through the process's tables (brdf/host/measured_registry.cpp). */
inline float microfacet_energy_albedo(Microfacet mf, float3 w) { return microfacet_energy_albedo(mf, bsdf_tables(), w); }
inline float microfacet_energy_average(Microfacet mf) { return microfacet_energy_average(mf, bsdf_tables()); }
#endif

#endif
