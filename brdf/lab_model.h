/* The lab's default model: a mixture of lobes, each physically plausible on its own, so the
 * mixture is too (never negative, reciprocal in reflection, directional albedo <= 1):
 *   f = w_d albedo [mix(mix(Lambert, Disney diffuse, retroreflection), HG single scattering, subsurface)]
 *     + w_g microfacet reflection with F0 = mix(fresnel, albedo, metallic)
 *     + w_s mirror with the same Fresnel (delta)
 *     + w_t albedo rough or smooth dielectric (ior)
 * The weights are the material's lobe weights normalised by their sum, after metallic moves the
 * diffuse weight onto the glossy lobe and the transmissive weight onto the mirror (metals are
 * opaque). With energy_compensation, the glossy lobe gains Kulla and Conty's multiple-scattering
 * lobe (brdf/energy_compensation.h). The sampler picks a lobe in proportion to an estimate of its
 * albedo at wo (lab_lobe_choice), and the returned pdf is the density of the whole mixture. */
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
#include "dielectric_lobe.h"
#endif
#if BRDF_FEATURE_ENERGY_COMPENSATION
#include "energy_compensation.h"
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

/* Whether the glossy lobe carries the multiple-scattering lobe. */
SS_FN bool lab_glossy_compensated(const Material* m, Microfacet mf) {
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GLOSSY
    return m->energy_compensation != 0 && !microfacet_is_smooth(mf);
#else
    return false;
#endif
}

/* Whether the rough dielectric carries its multiple-scattering lobes (GGX only: Hyper-Cauchy
 * dielectrics have no tables yet). */
SS_FN bool lab_dielectric_compensated(const Material* m, Microfacet mf) {
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_TRANSMISSION && BRDF_FEATURE_GGX
    return m->energy_compensation != 0 && mf.kind == BRDF_DISTRIBUTION_GGX && !lab_transmission_is_smooth(m, mf);
#else
    return false;
#endif
}

#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GLOSSY
/* F_ms f_ms of the glossy lobe, without its weight. */
SS_FN float3 lab_multiple_scattering_eval(const Material* m, Microfacet mf, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    float3 f_ms = multiple_scattering_fresnel(lab_specular_f0(m), microfacet_energy_average(mf, tables));
    return f_ms * multiple_scattering_eval(mf, tables, wo, wi);
}
#endif

#if BRDF_FEATURE_GLOSSY
/* How much more peaked than cosine-weighted the glossy lobe is at wo: pi f cos_i at the mirror
 * direction with F = 1, where the lobe peaks, over the single-scattering albedo's bound of 1 (a
 * Lambertian lobe gives 1), less 1; at most 0 where cosine sampling matches the lobe's peak. */
SS_FN float lab_glossy_peak_excess(Microfacet mf, float3 wo) {
    float3 mirror = make_float3(-wo.x, -wo.y, wo.z);
    return SS_PI * microfacet_reflection_eval(mf, float3_splat(1.0f), wo, mirror).x * mirror.z - 1.0f;
}
#endif

/* Probabilities of the sampling strategies at wo: cosine-weighted (the diffuse lobe's Lambert and
 * Disney parts, and the multiple-scattering lobe), the Henyey-Greenstein phase function (the
 * subsurface part), the glossy lobe's visible normals or its mirror, the mirror lobe, the dielectric.
 * Each is proportional to an estimate of what its lobe reflects at wo: the lobe weight times the
 * albedo (diffuse, dielectric), the Schlick Fresnel reflectance at wo (glossy, mirror) or
 * F_ms (1 - E(mu_o)) (multiple scattering), so a faint lobe is rarely sampled. A floor keeps every lobe that can be non-zero
 * sampleable. A glossy or subsurface sampler then keeps only the part of its lobe's probability that
 * its peak repays over cosine sampling, which takes the rest (docs/materials.md, Sampling). They
 * depend on wo only, so lab_pdf() recomputes them exactly. */
typedef struct LobeChoice {
    float cosine, subsurface, glossy, specular, transmission;
} LobeChoice;

#define BRDF_LOBE_CHOICE_FLOOR 1e-3f

SS_FN LobeChoice lab_lobe_choice(const Material* m, LobeWeights w, Microfacet mf, GLOBAL_MEM const float* tables, float3 wo) {
    LobeChoice c;
    float albedo = mean3(material_albedo(m)) + BRDF_LOBE_CHOICE_FLOOR;
    bool up = wo.z > 0.0f;
    float reflectance = up ? mean3(fresnel_schlick(lab_specular_f0(m), wo.z)) + BRDF_LOBE_CHOICE_FLOOR : 0.0f;
    float diffuse = up ? w.diffuse * albedo : 0.0f;
    c.subsurface = 0.0f;
#if BRDF_FEATURE_SUBSURFACE
    /* the phase function's sampler pays off only where its peak is denser than cosine sampling there:
     * p_HG at its peak (-wo mirrored up for g > 0, wo for g < 0) is (1 + |g|) / (4 pi (1 - |g|)^2), cosine
     * sampling's density there cos_o / pi. Its share grows with that excess and with |g| (near g = 0 the
     * lobe is close to cosine-shaped); cosine sampling takes the rest */
    if (up) {
        float g = fabs(m->subsurface_asymmetry);
        float peak = (1.0f + g) / (4.0f * sqr(1.0f - g) * wo.z);
        c.subsurface = diffuse * m->subsurface * g * clamp(peak - 1.0f, 0.0f, 1.0f);
    }
#endif
    c.cosine = diffuse - c.subsurface;
    c.glossy = w.glossy * reflectance;
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GLOSSY
    if (up && lab_glossy_compensated(m, mf))
        c.cosine += w.glossy * mean3(multiple_scattering_fresnel(lab_specular_f0(m), microfacet_energy_average(mf, tables))) *
                    multiple_scattering_albedo(mf, tables, wo);
#endif
    c.specular = w.specular * reflectance;
    c.transmission = w.transmission * albedo;
    /* divided rather than multiplied by 1 / sum: a lone lobe then gets probability 1 exactly */
    float sum = c.cosine + c.subsurface + c.glossy + c.specular + c.transmission;
    if (!(sum > 0.0f)) return c;
#if BRDF_FEATURE_GLOSSY
    /* the glossy lobe's own sampler gets the part of its share that its peak repays; cosine sampling
     * takes the rest. Next to other lobes, the sampler's directions below the horizon are lost and the
     * others are sampled less: a cost in proportion to the others' share 1 - q, against a gain in
     * proportion to the glossy lobe's share q and its peak's excess over cosine sampling. A lone glossy
     * lobe (q = 1) keeps its sampler, whose weights are at most 1. */
    if (up && c.glossy > 0.0f && !microfacet_is_smooth(mf)) {
        float q = c.glossy / sum;
        float share = q < 1.0f ? clamp(lab_glossy_peak_excess(mf, wo) * q / (1.0f - q), 0.0f, 1.0f) : 1.0f;
        c.cosine += c.glossy * (1.0f - share);
        c.glossy *= share;
    }
#endif
    c.cosine /= sum;
    c.subsurface /= sum;
    c.glossy /= sum;
    c.specular /= sum;
    c.transmission /= sum;
    return c;
}

/* lab_eval and lab_pdf for the lobe weights, microfacet and lobe choice that their callers computed
 * already: a sample (lab_sample) evaluates its mixture with the ones it drew from, instead of
 * computing them twice more (the Hyper-Cauchy microfacet takes four lgamma, the lobe choice a glossy
 * evaluation of its own). The same operations, so the same bits as lab_eval and lab_pdf. */
SS_FN float3 lab_eval_lobes(const Material* m, LobeWeights w, Microfacet mf, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    bool smooth = microfacet_is_smooth(mf);
    float3 f = float3_splat(0.0f);
    if (wo.z > 0.0f && wi.z > 0.0f) {
#if BRDF_FEATURE_DIFFUSE
        if (w.diffuse > 0.0f) f += material_albedo(m) * (w.diffuse * lab_diffuse_brdf(m, wo, wi));
#endif
#if BRDF_FEATURE_GLOSSY
        if (w.glossy > 0.0f && !smooth) f += w.glossy * microfacet_reflection_eval(mf, lab_specular_f0(m), wo, wi);
#endif
#if BRDF_FEATURE_ENERGY_COMPENSATION && BRDF_FEATURE_GLOSSY
        if (w.glossy > 0.0f && lab_glossy_compensated(m, mf)) f += w.glossy * lab_multiple_scattering_eval(m, mf, tables, wo, wi);
#endif
    }
#if BRDF_FEATURE_TRANSMISSION
    if (w.transmission > 0.0f && !lab_transmission_is_smooth(m, mf))
        f += material_albedo(m) * (w.transmission * dielectric_lobe_eval(mf, m->ior, lab_dielectric_compensated(m, mf), wo, wi));
#endif
    return f;
}

SS_FN float lab_pdf_lobes(const Material* m, Microfacet mf, LobeChoice c, float3 wo, float3 wi) {
    bool smooth = microfacet_is_smooth(mf);
    float pdf = 0.0f;
    if (wo.z > 0.0f && wi.z > 0.0f) {
        pdf += c.cosine * cosine_hemisphere_pdf(wi.z);
#if BRDF_FEATURE_SUBSURFACE
        if (c.subsurface > 0.0f) pdf += c.subsurface * henyey_greenstein_subsurface_pdf(wo, wi, m->subsurface_asymmetry);
#endif
#if BRDF_FEATURE_GLOSSY
        if (!smooth) pdf += c.glossy * microfacet_reflection_pdf(mf, wo, wi);
#endif
    }
#if BRDF_FEATURE_TRANSMISSION
    if (c.transmission > 0.0f && !lab_transmission_is_smooth(m, mf))
        pdf += c.transmission * dielectric_lobe_pdf(mf, m->ior, lab_dielectric_compensated(m, mf), wo, wi);
#endif
    return pdf;
}

SS_FN float3 lab_eval(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    return lab_eval_lobes(m, lab_lobe_weights(m), microfacet_from_material(m), tables, wo, wi);
}

SS_FN float lab_pdf(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    LobeWeights w = lab_lobe_weights(m);
    Microfacet mf = microfacet_from_material(m);
    return lab_pdf_lobes(m, mf, lab_lobe_choice(m, w, mf, tables, wo), wo, wi);
}

/* Mirror reflection with Schlick's Fresnel, as a delta sample of a lobe of weight `weight` picked with
 * probability `probability`. */
SS_FN BsdfSample lab_mirror_sample(const Material* m, float weight, float probability, float3 wo) {
    BsdfSample s = bsdf_sample_failed();
    if (!(wo.z > 0.0f)) return s;
    s.wi = make_float3(-wo.x, -wo.y, wo.z);
    s.pdf = probability;
    s.f = fresnel_schlick(lab_specular_f0(m), wo.z) * (weight / wo.z);
    s.flags = BSDF_REFLECTION | BSDF_DELTA;
    return s;
}

SS_FN BsdfSample lab_sample(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 u) {
    LobeWeights w = lab_lobe_weights(m);
    Microfacet mf = microfacet_from_material(m);
    LobeChoice c = lab_lobe_choice(m, w, mf, tables, wo);
    bool smooth = microfacet_is_smooth(mf);
    BsdfSample s = bsdf_sample_failed();
    float3 wi;
    /* pick a strategy with u.x, then stretch u.x back to [0, 1) for use inside the lobe */
    float uc = u.x;
    if (uc < c.cosine) {
        if (!(wo.z > 0.0f)) return s;
        wi = square_to_cosine_hemisphere(u.y, u.z);
    } else if ((uc -= c.cosine) < c.subsurface) {
#if BRDF_FEATURE_SUBSURFACE
        wi = henyey_greenstein_subsurface_sample(wo, m->subsurface_asymmetry, u.y, u.z);
#else
        return s;
#endif
    } else if ((uc -= c.subsurface) < c.glossy) {
        if (!(wo.z > 0.0f)) return s;
        if (smooth) return lab_mirror_sample(m, w.glossy, c.glossy, wo);
#if BRDF_FEATURE_GLOSSY
        if (!microfacet_reflection_sample_direction(mf, wo, u.y, u.z, &wi)) return s;
#else
        return s;
#endif
    } else if ((uc -= c.glossy) < c.specular) {
        return lab_mirror_sample(m, w.specular, c.specular, wo);
    } else if ((uc -= c.specular) < c.transmission) {
#if BRDF_FEATURE_TRANSMISSION
        float u_interface = fmin(uc / c.transmission, 0.99999994f);
        if (lab_transmission_is_smooth(m, mf)) {
            s = smooth_dielectric_sample(m->ior, wo, u_interface);
            s.f = s.f * material_albedo(m) * w.transmission;
            s.pdf *= c.transmission;
            return s;
        }
        if (!dielectric_lobe_sample_direction(mf, m->ior, lab_dielectric_compensated(m, mf), wo, u_interface, u.y, u.z, &wi)) return s;
#else
        return s;
#endif
    } else {
        return s; /* nothing to sample */
    }
    /* a continuous lobe: value and density of the whole mixture, so the pdf equals lab_pdf() */
    s.pdf = lab_pdf_lobes(m, mf, c, wo, wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.wi = wi;
    s.f = lab_eval_lobes(m, w, mf, tables, wo, wi);
    s.flags = same_hemisphere(wo, wi) ? BSDF_REFLECTION : BSDF_TRANSMISSION;
    return s;
}

#endif
