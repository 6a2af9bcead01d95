/* The BRDF module's entry points, shared by lobe plots, the IBL preview and the BDPT kernels.
 * Directions are unit vectors in the local shading frame (z = normal, x = tangent), both pointing
 * away from the surface: wo towards the viewer, wi towards the light. Every entry point clamps the
 * material to its documented ranges and turns the anisotropy tangent by tangent_rotation; the
 * *_clamped forms take a material that material_clamped() returned, for a caller that evaluates,
 * samples and weighs one material several times at one vertex and clamps it once.
 * `tables` is the BSDF's tables in global memory (brdf/bsdf_tables.h): the anisotropic energy table
 * and the blocks a BRDF_MODEL_MEASURED material reads at its measured_offset; kernels pass their
 * buffer argument. On the host, bsdf_eval, bsdf_pdf and bsdf_sample pass the process's registry
 * (brdf/host/measured_registry.hpp). */
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
#if BRDF_FEATURE_MEASURED
#include "measured.h"
#endif
#if BRDF_FEATURE_OPENPBR
#include "openpbr_model.h"
#endif
#if BRDF_FEATURE_EMISSION
#include "emission.h"
#endif

SS_FN float3 bsdf_eval_clamped(const Material* clamped, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    Material m = *clamped;
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_eval(&m, wo, wi);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) return lab_eval(&m, tables, wo, wi);
#endif
#if BRDF_FEATURE_MEASURED
    if (m.model == BRDF_MODEL_MEASURED) return merl_eval(tables + m.measured_offset, wo, wi);
#endif
#if BRDF_FEATURE_OPENPBR
    if (m.model == BRDF_MODEL_OPENPBR) return openpbr_eval(&m, tables, wo, wi);
#endif
    return float3_splat(0.0f);
}

SS_FN float bsdf_pdf_clamped(const Material* clamped, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    Material m = *clamped;
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    wi = rotate_about_normal(wi, -m.tangent_rotation);
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) return dtoadq2017_pdf(wo, wi);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) return lab_pdf(&m, tables, wo, wi);
#endif
#if BRDF_FEATURE_MEASURED
    if (m.model == BRDF_MODEL_MEASURED) return measured_pdf(tables + m.measured_offset, wo, wi);
#endif
#if BRDF_FEATURE_OPENPBR
    if (m.model == BRDF_MODEL_OPENPBR) return openpbr_pdf(&m, tables, wo, wi);
#endif
    return 0.0f;
}

/* u: three uniform numbers in [0, 1). */
SS_FN BsdfSample bsdf_sample_clamped(const Material* clamped, GLOBAL_MEM const float* tables, float3 wo, float3 u) {
    Material m = *clamped;
    wo = rotate_about_normal(wo, -m.tangent_rotation);
    BsdfSample s = bsdf_sample_failed();
#if BRDF_FEATURE_DTOADQ2017
    if (m.model == BRDF_MODEL_DTOADQ2017) s = dtoadq2017_sample(&m, wo, u);
#endif
#if BRDF_FEATURE_LAB_MODEL
    if (m.model == BRDF_MODEL_LAB) s = lab_sample(&m, tables, wo, u);
#endif
#if BRDF_FEATURE_MEASURED
    if (m.model == BRDF_MODEL_MEASURED) s = measured_sample(tables + m.measured_offset, wo, u);
#endif
#if BRDF_FEATURE_OPENPBR
    if (m.model == BRDF_MODEL_OPENPBR) s = openpbr_sample(&m, tables, wo, u);
#endif
    s.wi = rotate_about_normal(s.wi, m.tangent_rotation);
    return s;
}

SS_FN float3 bsdf_eval_tables(const Material* material, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    return bsdf_eval_clamped(&m, tables, wo, wi);
}

SS_FN float bsdf_pdf_tables(const Material* material, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    Material m = material_clamped(material);
    return bsdf_pdf_clamped(&m, tables, wo, wi);
}

SS_FN BsdfSample bsdf_sample_tables(const Material* material, GLOBAL_MEM const float* tables, float3 wo, float3 u) {
    Material m = material_clamped(material);
    return bsdf_sample_clamped(&m, tables, wo, u);
}

#ifndef __OPENCL_C_VERSION__
inline float3 bsdf_eval(const Material* m, float3 wo, float3 wi) { return bsdf_eval_tables(m, bsdf_tables(), wo, wi); }
inline float bsdf_pdf(const Material* m, float3 wo, float3 wi) { return bsdf_pdf_tables(m, bsdf_tables(), wo, wi); }
inline BsdfSample bsdf_sample(const Material* m, float3 wo, float3 u) { return bsdf_sample_tables(m, bsdf_tables(), wo, u); }
#endif

#endif
