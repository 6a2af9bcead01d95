/* The lab's default model: a mixture of lobes, each physically plausible on its own, so the
 * mixture is too (never negative, reciprocal in reflection, directional albedo <= 1):
 *   f = w_d albedo [mix(mix(Lambert, Disney diffuse, retroreflection), HG single scattering, subsurface)]
 *     + w_g microfacet reflection with F0 = mix(fresnel, albedo, metallic)
 *     + w_s mirror with the same Fresnel (delta)
 *     + w_t albedo rough or smooth dielectric (ior)
 * The weights are the material's lobe weights normalised by their sum, after metallic moves the
 * diffuse weight onto the glossy lobe and the transmissive weight onto the mirror (metals are
 * opaque). The sampler picks a lobe with exactly these weights, so the returned pdf is the density
 * of the whole mixture. */
#ifndef BRDF_LAB_MODEL_H
#define BRDF_LAB_MODEL_H
#include "bsdf_sample.h"
#include "single_source/vocabulary.h"
#include "features.h"
#include "frame.h"
#include "fresnel.h"
#include "material.h"
#include "microfacet.h"
#include "warp.h"
#if BRDF_FEATURE_DIFFUSE
#include "diffuse.h"
#endif
#if BRDF_FEATURE_SUBSURFACE
#include "henyey_greenstein.h"
#endif
#if BRDF_FEATURE_GLOSSY
#include "glossy.h"
#endif
#if BRDF_FEATURE_TRANSMISSION
#include "dielectric.h"
#endif

typedef struct LobeWeights {
    float diffuse, glossy, specular, transmission;
} LobeWeights;

SS_FN LobeWeights lab_lobe_weights(const Material* m) {
    LobeWeights w;
    w.diffuse = m->weight_diffuse * (1.0f - m->metallic);
    w.glossy = m->weight_glossy + m->weight_diffuse * m->metallic;
    w.specular = m->weight_specular + m->weight_transmission * m->metallic;
    w.transmission = m->weight_transmission * (1.0f - m->metallic);
    float sum = w.diffuse + w.glossy + w.specular + w.transmission;
    float scale = sum > 0.0f ? 1.0f / sum : 0.0f;
    w.diffuse *= scale;
    w.glossy *= scale;
    w.specular *= scale;
    w.transmission *= scale;
    return w;
}

/* An interface of index 1 does not bend light: whatever its roughness, transmission is the delta
 * wi = -wo, which only the smooth path represents. */
#define BRDF_INDEX_MATCHED_EPSILON 1e-3f

SS_FN bool lab_transmission_is_smooth(const Material* m, Microfacet mf) {
    return microfacet_is_smooth(mf) || fabs(m->ior - 1.0f) < BRDF_INDEX_MATCHED_EPSILON;
}

SS_FN float3 lab_specular_f0(const Material* m) { return specular_f0(material_albedo(m), m->fresnel, m->metallic); }

#if BRDF_FEATURE_DIFFUSE
SS_FN float lab_diffuse_brdf(const Material* m, float3 wo, float3 wi) {
    float base = lambert_brdf();
#if BRDF_FEATURE_RETROREFLECTION
    base = mix(base, disney_diffuse_brdf(m->roughness, wo, wi), m->retroreflection);
#endif
#if BRDF_FEATURE_SUBSURFACE
    base = mix(base, henyey_greenstein_subsurface_brdf(wo, wi, m->subsurface_asymmetry), m->subsurface);
#endif
    return base;
}
#endif

SS_FN float3 lab_eval(const Material* m, float3 wo, float3 wi) {
    LobeWeights w = lab_lobe_weights(m);
    Microfacet mf = microfacet_from_material(m);
    bool smooth = microfacet_is_smooth(mf);
    float3 f = float3_splat(0.0f);
    if (wo.z > 0.0f && wi.z > 0.0f) {
#if BRDF_FEATURE_DIFFUSE
        if (w.diffuse > 0.0f) f += material_albedo(m) * (w.diffuse * lab_diffuse_brdf(m, wo, wi));
#endif
#if BRDF_FEATURE_GLOSSY
        if (w.glossy > 0.0f && !smooth) f += w.glossy * microfacet_reflection_eval(mf, lab_specular_f0(m), wo, wi);
#endif
    }
#if BRDF_FEATURE_TRANSMISSION
    if (w.transmission > 0.0f && !lab_transmission_is_smooth(m, mf))
        f += material_albedo(m) * (w.transmission * rough_dielectric_eval(mf, m->ior, wo, wi));
#endif
    return f;
}

SS_FN float lab_pdf(const Material* m, float3 wo, float3 wi) {
    LobeWeights w = lab_lobe_weights(m);
    Microfacet mf = microfacet_from_material(m);
    bool smooth = microfacet_is_smooth(mf);
    float pdf = 0.0f;
    if (wo.z > 0.0f && wi.z > 0.0f) {
#if BRDF_FEATURE_DIFFUSE
        pdf += w.diffuse * cosine_hemisphere_pdf(wi.z);
#endif
#if BRDF_FEATURE_GLOSSY
        if (!smooth) pdf += w.glossy * microfacet_reflection_pdf(mf, wo, wi);
#endif
    }
#if BRDF_FEATURE_TRANSMISSION
    if (w.transmission > 0.0f && !lab_transmission_is_smooth(m, mf))
        pdf += w.transmission * rough_dielectric_pdf(mf, m->ior, wo, wi);
#endif
    return pdf;
}

/* Mirror reflection with Schlick's Fresnel, as a delta sample picked with probability `weight`. */
SS_FN BsdfSample lab_mirror_sample(const Material* m, float weight, float3 wo) {
    BsdfSample s = bsdf_sample_failed();
    if (!(wo.z > 0.0f)) return s;
    s.wi = make_float3(-wo.x, -wo.y, wo.z);
    s.pdf = weight;
    s.f = fresnel_schlick(lab_specular_f0(m), wo.z) * (weight / wo.z);
    s.flags = BSDF_REFLECTION | BSDF_DELTA;
    return s;
}

SS_FN BsdfSample lab_sample(const Material* m, float3 wo, float3 u) {
    LobeWeights w = lab_lobe_weights(m);
    Microfacet mf = microfacet_from_material(m);
    bool smooth = microfacet_is_smooth(mf);
    BsdfSample s = bsdf_sample_failed();
    float3 wi;
    /* pick a lobe with u.x, then stretch u.x back to [0, 1) for use inside the lobe */
    float uc = u.x;
    if (uc < w.diffuse) {
        if (!(wo.z > 0.0f)) return s;
        wi = square_to_cosine_hemisphere(u.y, u.z);
    } else if ((uc -= w.diffuse) < w.glossy) {
        if (!(wo.z > 0.0f)) return s;
        if (smooth) return lab_mirror_sample(m, w.glossy, wo);
#if BRDF_FEATURE_GLOSSY
        if (!microfacet_reflection_sample_direction(mf, wo, u.y, u.z, &wi)) return s;
#else
        return s;
#endif
    } else if ((uc -= w.glossy) < w.specular) {
        return lab_mirror_sample(m, w.specular, wo);
    } else if ((uc -= w.specular) < w.transmission) {
#if BRDF_FEATURE_TRANSMISSION
        float u_interface = fmin(uc / w.transmission, 0.99999994f);
        if (lab_transmission_is_smooth(m, mf)) {
            s = smooth_dielectric_sample(m->ior, wo, u_interface);
            s.f = s.f * material_albedo(m) * w.transmission;
            s.pdf *= w.transmission;
            return s;
        }
        if (!rough_dielectric_sample_direction(mf, m->ior, wo, u_interface, u.y, u.z, &wi)) return s;
#else
        return s;
#endif
    } else {
        return s; /* all weights zero */
    }
    /* a continuous lobe: value and density of the whole mixture, so the pdf equals lab_pdf() */
    s.pdf = lab_pdf(m, wo, wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.wi = wi;
    s.f = lab_eval(m, wo, wi);
    s.flags = same_hemisphere(wo, wi) ? BSDF_REFLECTION : BSDF_TRANSMISSION;
    return s;
}

#endif
