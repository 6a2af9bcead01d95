/* One microfacet distribution, GGX or Hyper-Cauchy, behind one interface: D, Smith masking
 * (uncorrelated G1 and height-correlated G2, Heitz 2014 eq. 99) and the sampled normal's density. */
#ifndef BRDF_MICROFACET_H
#define BRDF_MICROFACET_H
#include "single_source/vocabulary.h"
#include "features.h"
#include "material.h"
#if BRDF_FEATURE_GGX
#include "ggx.h"
#endif
#if BRDF_FEATURE_HYPER_CAUCHY
#include "hyper_cauchy.h"
#endif

/* Below this alpha a surface is treated as smooth: its lobe becomes a delta (mirror / refraction). */
#define BRDF_SMOOTH_ALPHA 1e-3f
#define BRDF_MIN_ALPHA 1e-4f

typedef struct Microfacet {
    int kind;   /* BRDF_DISTRIBUTION_* */
    float ax;   /* GGX alpha along the tangent; Hyper-Cauchy width is alpha / sqrt(2) */
    float ay;   /* ... along the bitangent */
    float shape;
#if BRDF_FEATURE_HYPER_CAUCHY
    HyperCauchyShape hc; /* Hyper-Cauchy only: hyper_cauchy_shape(shape), once per evaluation */
#endif
} Microfacet;

SS_FN Microfacet microfacet_make(int kind, float ax, float ay, float shape) {
    Microfacet mf;
    mf.kind = kind;
    mf.ax = ax;
    mf.ay = ay;
    mf.shape = shape;
#if BRDF_FEATURE_HYPER_CAUCHY
    mf.hc.log_norm = mf.hc.log_c = mf.hc.student_log_norm = mf.hc.student_k = 0.0f;
    if (kind == BRDF_DISTRIBUTION_HYPER_CAUCHY) mf.hc = hyper_cauchy_shape(shape);
#endif
    return mf;
}

/* Disney's anisotropy mapping (Burley 2012): aspect = sqrt(1 - 0.9 anisotropic). */
SS_FN Microfacet microfacet_from_material(const Material* m) {
    float alpha = fmax(sqr(m->roughness), BRDF_MIN_ALPHA);
    float aspect = sqrt(1.0f - 0.9f * m->anisotropic);
    return microfacet_make(m->distribution, fmax(alpha / aspect, BRDF_MIN_ALPHA), fmax(alpha * aspect, BRDF_MIN_ALPHA), m->hc_shape);
}

SS_FN bool microfacet_is_smooth(Microfacet mf) { return fmax(mf.ax, mf.ay) < BRDF_SMOOTH_ALPHA; }

#define BRDF_INV_SQRT2 0.70710678118654752440f

/* With a distribution switched off (brdf/features.h) its branch compiles to nothing; the host never
 * hands such a kernel a material that uses it. */
SS_FN float microfacet_d(Microfacet mf, float3 m) {
#if BRDF_FEATURE_HYPER_CAUCHY
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY)
        return hyper_cauchy_d(m, mf.ax * BRDF_INV_SQRT2, mf.ay * BRDF_INV_SQRT2, mf.shape);
#endif
#if BRDF_FEATURE_GGX
    return ggx_d(m, mf.ax, mf.ay);
#else
    return 0.0f;
#endif
}

SS_FN float microfacet_lambda(Microfacet mf, float3 w) {
#if BRDF_FEATURE_HYPER_CAUCHY
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY)
        return hyper_cauchy_lambda(w, mf.ax * BRDF_INV_SQRT2, mf.ay * BRDF_INV_SQRT2, mf.shape, mf.hc);
#endif
#if BRDF_FEATURE_GGX
    return ggx_lambda(w, mf.ax, mf.ay);
#else
    return 0.0f;
#endif
}

SS_FN float microfacet_g1(Microfacet mf, float3 w) { return 1.0f / (1.0f + microfacet_lambda(mf, w)); }

SS_FN float microfacet_g2(Microfacet mf, float3 wo, float3 wi) {
    return 1.0f / (1.0f + microfacet_lambda(mf, wo) + microfacet_lambda(mf, wi));
}

/* Samples a microfacet normal on the upper side from the visible normals of wo (either distribution). */
SS_FN float3 microfacet_sample_normal(Microfacet mf, float3 wo, float u1, float u2) {
#if BRDF_FEATURE_HYPER_CAUCHY
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY)
        return hyper_cauchy_sample_visible_normal(wo, mf.ax * BRDF_INV_SQRT2, mf.ay * BRDF_INV_SQRT2, mf.shape, mf.hc, u1, u2);
#endif
#if BRDF_FEATURE_GGX
    return ggx_sample_visible_normal(wo, mf.ax, mf.ay, u1, u2);
#else
    return make_float3(0.0f, 0.0f, 1.0f);
#endif
}

/* Density of microfacet_sample_normal() over solid angle of m, G1(wo) |wo.m| D(m) / |cos theta_o|. The caller passes wo_m = |wo . m|:
 * where m is a half vector it knows this more accurately than a dot product of nearly
 * perpendicular vectors would give it. */
SS_FN float microfacet_normal_pdf(Microfacet mf, float3 wo, float3 m, float wo_m) {
    float cos_o = fabs(wo.z);
    if (!(wo_m > 0.0f) || !(cos_o > 0.0f)) return 0.0f;
    return microfacet_g1(mf, wo) * wo_m * microfacet_d(mf, m) / cos_o;
}

#endif
