/* Microfacet reflection off a dielectric interface with the exact Fresnel reflectance: OpenPBR's
 * coat and the specular of its dielectric base. f = F(wo.h, eta) D(h) G2(wo, wi) / (4 cos_o cos_i),
 * eta the index below over the index above; sampled as the glossy lobe (brdf/glossy.h), whose pdf
 * it shares. F depends on |wo + wi| / 2 = wo.h = wi.h only, so f is exactly reciprocal. */
#ifndef BRDF_DIELECTRIC_REFLECTION_H
#define BRDF_DIELECTRIC_REFLECTION_H
#include "single_source/vocabulary.h"
#include "fresnel.h"
#include "microfacet.h"

/* D G2 / (4 cos_o cos_i) and the cosine wo.h, for wo and wi on the upper side; 0 elsewhere. */
SS_FN float microfacet_reflection_shape(Microfacet mf, float3 wo, float3 wi, float* wo_h) {
    *wo_h = 1.0f;
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float3 sum = wo + wi;
    float len = length(sum);
    if (!(len > 0.0f)) return 0.0f;
    *wo_h = 0.5f * len;
    return microfacet_d(mf, sum / len) * microfacet_g2(mf, wo, wi) / (4.0f * wo.z * wi.z);
}

SS_FN float dielectric_reflection_eval(Microfacet mf, float eta, float3 wo, float3 wi) {
    float wo_h;
    float shape = microfacet_reflection_shape(mf, wo, wi, &wo_h);
    return shape > 0.0f ? shape * fresnel_dielectric(wo_h, eta) : 0.0f;
}

/* The index whose normal reflectance is `weight` times that of eta: OpenPBR's specular_weight,
 * which scales F0 = ((eta - 1) / (eta + 1))^2 and keeps the Fresnel curve of a real interface. */
SS_FN float dielectric_weighted_ior(float eta, float weight) {
    float r = sqrt(weight) * (eta - 1.0f) / (eta + 1.0f);
    return (1.0f + r) / (1.0f - r);
}

#endif
