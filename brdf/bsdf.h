/* The BRDF module's entry points, shared by lobe plots, the IBL preview and the BDPT kernels.
 * Directions are unit vectors in the local shading frame (z = normal, x = tangent), both pointing
 * away from the surface: wo towards the viewer, wi towards the light. Every entry point clamps the
 * material to its documented ranges and turns the anisotropy tangent by tangent_rotation. */
#ifndef BRDF_BSDF_H
#define BRDF_BSDF_H
#include "bsdf_sample.h"
#include "common.h"
#include "dtoadq2017_model.h"
#include "frame.h"
#include "lab_model.h"
#include "material.h"

BRDF_FN float3 bsdf_eval(const Material* material, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_eval(&m, wo, wi);
    return lab_eval(&m, wo, wi);
}

BRDF_FN float bsdf_pdf(const Material* material, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_pdf(wo, wi);
    return lab_pdf(&m, wo, wi);
}

/* u: three uniform numbers in [0, 1). */
BRDF_FN BsdfSample bsdf_sample(const Material* material, float3 wo, float3 u) {
    Material m = material_clamped(material);
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    BsdfSample s = m.model == BRDF_MODEL_DTOADQ2017 ? dtoadq2017_sample(&m, wo, u) : lab_sample(&m, wo, u);
    s.wi = rotate_about_normal(s.wi, m.tangent_rotation);
    return s;
}

#endif
