/* The rough dielectric interface as a lobe of a model: single scattering (brdf/dielectric.h) plus,
 * where `compensated`, Kulla and Conty's multiple-scattering lobes (brdf/dielectric_compensation.h,
 * GGX only), which the sampler picks with their share of the white interface's albedo. Shared by the
 * lab model's transmissive lobe and OpenPBR's transmission. */
#ifndef BRDF_DIELECTRIC_LOBE_H
#define BRDF_DIELECTRIC_LOBE_H
#include "single_source/vocabulary.h"
#include "dielectric.h"
#include "features.h"
#include "microfacet.h"
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GGX
#include "dielectric_compensation.h"
#endif

SS_FN float dielectric_lobe_eval(Microfacet mf, float eta, bool compensated, float3 wo, float3 wi) {
    float interface = rough_dielectric_eval(mf, eta, wo, wi);
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GGX
    if (compensated) interface += dielectric_multiple_scattering_eval(mf, eta, wo, wi);
#endif
    return interface;
}

SS_FN float dielectric_lobe_pdf(Microfacet mf, float eta, bool compensated, float3 wo, float3 wi) {
    float interface = rough_dielectric_pdf(mf, eta, wo, wi);
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GGX
    if (compensated) {
        DielectricEnergy d = dielectric_energy(mf, eta, wo);
        interface = (1.0f - d.lost_o) * interface + d.lost_o * dielectric_multiple_scattering_pdf(d, wo, wi);
    }
#endif
    return interface;
}

/* uc in [0, 1) picks single or multiple scattering, then reflection or refraction. */
SS_FN bool dielectric_lobe_sample_direction(Microfacet mf, float eta, bool compensated, float3 wo, float uc, float u1, float u2, float3* wi) {
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GGX
    if (compensated) {
        if (wo.z == 0.0f) return false;
        DielectricEnergy d = dielectric_energy(mf, eta, wo);
        if (uc < d.lost_o) {
            *wi = dielectric_multiple_scattering_sample(d, wo, uc / d.lost_o, u1, u2);
            return true;
        }
        uc = fmin((uc - d.lost_o) / (1.0f - d.lost_o), 0.99999994f);
    }
#endif
    return rough_dielectric_sample_direction(mf, eta, wo, uc, u1, u2, wi);
}

#endif
