/* A rough dielectric interface, reflection and transmission (Walter et al. 2007, in the form of
 * pbrt-v4's DielectricBxDF), and its smooth limit. Local frame, the inside is z < 0, eta is the
 * index of the inside over the outside.
 * Transmission is written in its flux-conserving form, without the 1/eta^2 radiance scaling: the
 * scaling cancels for paths that enter and leave a closed object, and without it the directional
 * albedo is at most 1 from both sides. */
#ifndef BRDF_DIELECTRIC_H
#define BRDF_DIELECTRIC_H
#include "bsdf_sample.h"
#include "single_source/vocabulary.h"
#include "frame.h"
#include "fresnel.h"
#include "microfacet.h"

/* Generalised half vector of (wo, wi) on the upper side, and the relative index seen from wo.
 * Returns false where the pair has no valid microfacet (grazing, degenerate or back-facing). */
SS_FN bool dielectric_half_vector(float3 wo, float3 wi, float eta, float3* wm, float* etap) {
    float cos_o = wo.z, cos_i = wi.z;
    if (cos_o == 0.0f || cos_i == 0.0f) return false;
    bool reflect = cos_o * cos_i > 0.0f;
    *etap = reflect ? 1.0f : (cos_o > 0.0f ? eta : 1.0f / eta);
    float3 m = wi * (*etap) + wo;
    float len2 = dot(m, m);
    if (!(len2 > 1e-12f)) return false;
    m = m / sqrt(len2);
    if (m.z < 0.0f) m = -m;
    if (dot(m, wi) * cos_i < 0.0f || dot(m, wo) * cos_o < 0.0f) return false;
    *wm = m;
    return true;
}

SS_FN float rough_dielectric_eval(Microfacet mf, float eta, float3 wo, float3 wi) {
    float3 wm;
    float etap;
    if (!dielectric_half_vector(wo, wi, eta, &wm, &etap)) return 0.0f;
    float fr = fresnel_dielectric(dot(wo, wm), eta);
    float d = microfacet_d(mf, wm), g = microfacet_g2(mf, wo, wi);
    if (etap == 1.0f && same_hemisphere(wo, wi)) return d * g * fr / fabs(4.0f * wo.z * wi.z);
    float denom = sqr(dot(wi, wm) + dot(wo, wm) / etap);
    return d * g * (1.0f - fr) * fabs(dot(wi, wm) * dot(wo, wm) / (wi.z * wo.z * denom));
}

SS_FN float rough_dielectric_pdf(Microfacet mf, float eta, float3 wo, float3 wi) {
    float3 wm;
    float etap;
    if (!dielectric_half_vector(wo, wi, eta, &wm, &etap)) return 0.0f;
    float fr = fresnel_dielectric(dot(wo, wm), eta);
    float pdf_m = microfacet_normal_pdf(mf, wo, wm, fabs(dot(wo, wm)));
    if (etap == 1.0f && same_hemisphere(wo, wi)) return pdf_m / (4.0f * fabs(dot(wo, wm))) * fr;
    float denom = sqr(dot(wi, wm) + dot(wo, wm) / etap);
    return pdf_m * fabs(dot(wi, wm)) / denom * (1.0f - fr);
}

/* Samples a direction of the rough interface; the caller evaluates f and pdf of its whole mixture
 * for it. uc picks reflection or refraction by the Fresnel reflectance of the sampled facet. */
SS_FN bool rough_dielectric_sample_direction(Microfacet mf, float eta, float3 wo, float uc, float u1, float u2, float3* wi) {
    if (wo.z == 0.0f) return false;
    float3 wm = microfacet_sample_normal(mf, wo, u1, u2);
    float cos_om = dot(wo, wm);
    /* the facet must face wo, as dielectric_half_vector() requires; a visible normal does, up to
     * rounding at grazing incidence */
    if (!(cos_om * wo.z > 0.0f)) return false;
    float3 n = cos_om >= 0.0f ? wm : -wm;  /* the facet normal on wo's side */
    float fr = fresnel_dielectric(cos_om, eta);
    if (uc < fr) {
        *wi = reflect_about(wo, wm);
        if (!same_hemisphere(wo, *wi)) return false;
    } else {
        float eta_rel = cos_om >= 0.0f ? eta : 1.0f / eta;
        if (!refract_through(wo, n, eta_rel, wi) || same_hemisphere(wo, *wi)) return false;
    }
    /* keep only directions rough_dielectric_pdf() accounts for */
    float3 wm_check;
    float etap;
    return dielectric_half_vector(wo, *wi, eta, &wm_check, &etap);
}

/* The smooth limit: mirror reflection with probability F, refraction otherwise. */
SS_FN BsdfSample smooth_dielectric_sample(float eta, float3 wo, float uc) {
    BsdfSample s = bsdf_sample_failed();
    if (wo.z == 0.0f) return s;
    float fr = fresnel_dielectric(wo.z, eta);
    if (uc < fr) {
        s.wi = make_float3(-wo.x, -wo.y, wo.z);
        s.pdf = fr;
        s.f = float3_splat(fr / fabs(s.wi.z));
        s.flags = BSDF_REFLECTION | BSDF_DELTA;
        return s;
    }
    float3 n = make_float3(0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f);
    float3 wi;
    if (!refract_through(wo, n, wo.z > 0.0f ? eta : 1.0f / eta, &wi) || wi.z == 0.0f) return s;
    s.wi = wi;
    s.pdf = 1.0f - fr;
    s.f = float3_splat((1.0f - fr) / fabs(wi.z));
    s.flags = BSDF_TRANSMISSION | BSDF_DELTA;
    return s;
}

#endif
