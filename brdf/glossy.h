/* Microfacet reflection with Schlick's Fresnel: the glossy lobe of conductors and of the dielectric
 * coat. f = F(wi.h) D(h) G2(wo, wi) / (4 cos_o cos_i) (Cook and Torrance 1982, Walter et al. 2007). */
#ifndef BRDF_GLOSSY_H
#define BRDF_GLOSSY_H
#include "single_source/vocabulary.h"
#include "frame.h"
#include "fresnel.h"
#include "microfacet.h"

SS_FN float3 microfacet_reflection_eval(Microfacet mf, float3 f0, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return float3_splat(0.0f);
    float3 sum = wo + wi;
    float len = length(sum);
    if (!(len > 0.0f)) return float3_splat(0.0f);
    float3 h = sum / len;
    float d = microfacet_d(mf, h);
    float g = microfacet_g2(mf, wo, wi);
    /* wi.h = wo.h = |wo + wi| / 2: symmetric in its arguments, so f is exactly reciprocal */
    return fresnel_schlick(f0, 0.5f * len) * (d * g / (4.0f * wo.z * wi.z));
}

/* Density of reflecting wo about a sampled normal: pdf(h) / (4 wo.h). For unit wo and wi,
 * wo.h = |wo + wi| / 2 exactly; a computed dot product is rounding noise when wi is near the
 * mirror of a grazing wo, and would cut the pdf off where eval has no such cut. */
SS_FN float microfacet_reflection_pdf(Microfacet mf, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float3 sum = wo + wi;
    float len = length(sum);
    if (!(len > 0.0f)) return 0.0f;
    float wo_h = 0.5f * len;
    return microfacet_normal_pdf(mf, wo, sum / len, wo_h) / (4.0f * wo_h);
}

/* Reflects wo about a sampled normal; false where that gives no direction microfacet_reflection_pdf()
 * accounts for (a normal facing away from wo, or a reflection below the horizon). */
SS_FN bool microfacet_reflection_sample_direction(Microfacet mf, float3 wo, float u1, float u2, float3* wi) {
    if (!(wo.z > 0.0f)) return false;
    float3 m = microfacet_sample_normal(mf, wo, u1, u2);
    if (!(dot(wo, m) > 0.0f)) return false;
    *wi = reflect_about(wo, m);
    return wi->z > 0.0f;
}

#endif
