/* The BRDF module's entry points, shared by lobe plots, the IBL preview and the BDPT kernels.
 * Directions are unit vectors in the local shading frame (z = normal, x = tangent), both pointing
 * away from the surface: wo towards the viewer, wi towards the light. Every entry point clamps the
 * material to its documented ranges and turns the anisotropy tangent by tangent_rotation. */
#ifndef BRDF_BSDF_H
#define BRDF_BSDF_H
#include "bsdf_sample.h"
#include "single_source/vocabulary.h"
#include "features.h"
#include "frame.h"
#include "material.h"
#if BRDF_FEATURE_LAB_MODEL
#include "lab_model.h"
#endif
#if BRDF_FEATURE_DTOADQ2017
#include "dtoadq2017_model.h"
#endif

SS_FN float3 bsdf_eval(const Material* material, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_eval(&m, wo, wi);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) return lab_eval(&m, wo, wi);
#endif
    return float3_splat(0.0f);
}

SS_FN float bsdf_pdf(const Material* material, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_pdf(wo, wi);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) return lab_pdf(&m, wo, wi);
#endif
    return 0.0f;
}

/* u: three uniform numbers in [0, 1). */
SS_FN BsdfSample bsdf_sample(const Material* material, float3 wo, float3 u) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    BsdfSample s = bsdf_sample_failed();
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) s = dtoadq2017_sample(&m, wo, u);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) s = lab_sample(&m, wo, u);
#endif
    s.wi = rotate_about_normal(s.wi, m.tangent_rotation);
    return s;
}

#endif
