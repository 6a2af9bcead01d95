/* OpenPBR Surface 1.1 (Andersson et al. 2024) as the lab evaluates it: fuzz over coat over the base
 * mix, each layer passing down what it does not reflect by albedo scaling, as the specification's
 * reference implementation does:
 *   f = f_fuzz + (1 - E_fuzz(mu_o)) [ f_coat + (1 - E_coat(mu_o)) T(wo) T(wi) D f_base ]
 *   f_base = metalness f_metal + (1 - metalness) [ (1 - transmission) f_opaque + transmission f_glass ]
 *   f_opaque = f_specular + (1 - E_specular(mu_o)) [ (1 - subsurface) f_EON + subsurface f_HG ]
 * with each layer's weight mixing it in (coat_weight 0 leaves the base as it is). The lobes:
 *   fuzz      Charlie sheen (brdf/sheen.h), fuzz_color, divided by max(1, its albedo at mu_o);
 *   coat      GGX reflection off a dielectric of coat_ior with its exact Fresnel
 *             (brdf/dielectric_reflection.h); T(w) = coat_color^(1 / (2 mu_t(w))) the absorption
 *             along the refracted path (mu_t the cosine inside the coat: coat_color is the tint of
 *             the base at normal incidence, in and out); D the darkening by light the coat reflects
 *             back down, (1 - K) / (1 - rho K), K = 1 - (1 - E_avg,coat) / coat_ior^2 its internal
 *             reflectance, rho the base colour, applied in proportion to coat_darkening. The coat
 *             roughens the specular below: r^4 -> min(1, r^4 + 2 coat_roughness^4), by coat_weight;
 *   metal     GGX with the F82-tint Fresnel (brdf/fresnel.h) of F0 = base_weight base_color and
 *             tint specular_color, times specular_weight; Kulla-Conty multiple scattering; the thin
 *             film's change of an equivalent conductor's reflectance added by thin_film_weight;
 *   specular  GGX reflection off the dielectric of specular_ior, its F0 scaled by specular_weight
 *             (through the index, brdf/dielectric_reflection.h), tinted by specular_color, with the
 *             thin film's Airy reflectance (brdf/thin_film.h) mixed into its Fresnel by
 *             thin_film_weight;
 *   diffuse   energy-preserving Oren-Nayar (brdf/eon_diffuse.h), base_weight base_color;
 *   subsurface the lab's Henyey-Greenstein single-scattering lobe (brdf/henyey_greenstein.h), g
 *             subsurface_scatter_anisotropy, subsurface_color: a BRDF standing for the volume;
 *   glass     the rough dielectric (brdf/dielectric_lobe.h), reflection and refraction, tinted by
 *             transmission_color at the interface (the renderer has no participating media).
 * The E are tabulated directional albedos (brdf/openpbr_energy.h), exact for smooth interfaces.
 * Albedo scaling by E(mu_o) keeps every layer's energy within what the one above lets through, and a
 * white, non-absorbing stack reflects all of it, but it is not reciprocal (docs/materials.md gives
 * the measured departure). Layers are one-sided: from inside (wo below), only the glass applies.
 * Smooth interfaces (coat, specular, metal, glass) are delta lobes, sampled as such. The sampler picks
 * a lobe in proportion to an estimate of its albedo at wo; the pdf is the whole mixture's. */
#ifndef BRDF_OPENPBR_MODEL_H
#define BRDF_OPENPBR_MODEL_H
#include "bsdf_sample.h"
#include "single_source/vocabulary.h"
#include "dielectric_reflection.h"
#include "features.h"
#include "frame.h"
#include "fresnel.h"
#include "glossy.h"
#include "material.h"
#include "microfacet.h"
#include "openpbr_energy.h"
#include "warp.h"
#if BRDF_FEATURE_DIFFUSE
#include "eon_diffuse.h"
#endif
#if BRDF_FEATURE_SUBSURFACE
#include "henyey_greenstein.h"
#endif
#if BRDF_FEATURE_TRANSMISSION
#include "dielectric_lobe.h"
#endif
#if BRDF_FEATURE_THIN_FILM
#include "thin_film.h"
#endif
#if BRDF_FEATURE_ENERGY_COMPENSATION
#include "energy_compensation.h"
#endif

/* OpenPBR's anisotropy: alpha = roughness^2 stretched to alpha_t = alpha sqrt(2 / (1 + (1 - a)^2)) along
 * the tangent and alpha_b = (1 - a) alpha_t, which keeps alpha_t^2 + alpha_b^2 = 2 alpha^2 (the lab
 * model's Disney mapping keeps alpha_t alpha_b = alpha^2 instead). */
SS_FN Microfacet openpbr_microfacet(float roughness, float anisotropy) {
    float alpha = roughness * roughness;
    float alpha_t = alpha * sqrt(2.0f / (1.0f + sqr(1.0f - anisotropy)));
    float alpha_b = (1.0f - anisotropy) * alpha_t;
    return microfacet_make(BRDF_DISTRIBUTION_GGX, fmax(alpha_t, BRDF_MIN_ALPHA), fmax(alpha_b, BRDF_MIN_ALPHA), 2.0f);
}

/* What the material and wo fix: the interfaces, the lobe weights and every layer's albedo at wo. */
typedef struct OpenPbr {
    Microfacet specular, coat;
    float eta;                 /* specular_ior with its F0 scaled by specular_weight */
    float3 base;               /* base_weight base_color */
    float metal, opaque, glass; /* weights of the base's metal, opaque dielectric and transmissive dielectric */
    bool specular_smooth, coat_smooth, glass_smooth, metal_compensated, glass_compensated;
    float fuzz_albedo;         /* fuzz_weight times the normalised sheen's albedo at mu_o */
    float fuzz_normalisation;  /* 1 / max(1, E_sheen(mu_o)) */
    float coat_albedo;         /* E_coat(mu_o) */
    float3 specular_albedo;    /* what the dielectric specular reflects at mu_o, film and tint included (0 without an opaque dielectric) */
    float3 darkening;          /* D, mixed in by coat_darkening */
    GLOBAL_MEM const float* tables; /* the BSDF's tables (brdf/bsdf_tables.h): the metal's anisotropic energy */
} OpenPbr;

/* The dielectric specular's Fresnel reflectance at cos, with the thin film mixed in. */
SS_FN float3 openpbr_specular_fresnel(const Material* m, float eta, float cos_angle) {
    float3 f = float3_splat(fresnel_dielectric(clamp(cos_angle, 0.0f, 1.0f), eta));
#if BRDF_FEATURE_THIN_FILM
    if (m->thin_film_weight > 0.0f)
        f = mix(f, thin_film_reflectance_rgb(cos_angle, 1.0f, m->thin_film_ior, eta, m->thin_film_thickness), m->thin_film_weight);
#endif
    return f;
}

/* What the film adds to the specular's Fresnel reflectance at cos (0 without a film). */
SS_FN float3 openpbr_film_change(const Material* m, float eta, float cos_angle) {
#if BRDF_FEATURE_THIN_FILM
    if (m->thin_film_weight > 0.0f)
        return openpbr_specular_fresnel(m, eta, cos_angle) - float3_splat(fresnel_dielectric(clamp(cos_angle, 0.0f, 1.0f), eta));
#endif
    return float3_splat(0.0f);
}

#if BRDF_FEATURE_THIN_FILM
/* One channel of the metal's Fresnel under a film (thickness > 0) at wavenumber nu (deviation
 * sigma_nu): the F82-tint value f82 plus what the film changes of the reflectance of the conductor
 * of the same F0 and edge tint (conductor_index_from_tint, as OpenPBR's reference viewer takes it),
 * weighted by thin_film_weight; in [0, 1]. At normal incidence both curves are F0, so there it is
 * that conductor's film reflectance. */
SS_FN float openpbr_metal_film_channel(const Material* m, float f82, float f0, float tint, float cos_angle, float nu, float sigma_nu) {
    float2 n = conductor_index_from_tint(f0, tint);
    float change = thin_film_conductor_change(clamp(cos_angle, 0.0f, 1.0f), m->thin_film_ior, n, m->thin_film_thickness, nu, sigma_nu);
    return clamp(f82 + m->thin_film_weight * change, 0.0f, 1.0f);
}
#endif

/* The metal's Fresnel: F82 tint of F0 = base and tint specular_color, with the thin film where there
 * is one, times specular_weight. A film of weight or thickness 0 leaves F82 bit for bit. */
SS_FN float3 openpbr_metal_fresnel(const Material* m, float3 base, float cos_angle) {
    float3 tint = float3_from_array(m->specular_color);
    float3 f = fresnel_f82_tint(base, tint, cos_angle);
#if BRDF_FEATURE_THIN_FILM
    if (m->thin_film_weight > 0.0f && m->thin_film_thickness > 0.0f)
        f = make_float3(openpbr_metal_film_channel(m, f.x, base.x, tint.x, cos_angle, THIN_FILM_NU_R, THIN_FILM_SIGMA_NU),
                        openpbr_metal_film_channel(m, f.y, base.y, tint.y, cos_angle, THIN_FILM_NU_G, THIN_FILM_SIGMA_NU),
                        openpbr_metal_film_channel(m, f.z, base.z, tint.z, cos_angle, THIN_FILM_NU_B, THIN_FILM_SIGMA_NU));
#endif
    return f * m->specular_weight;
}

/* The specular roughness under a coat of weight w: r^4 -> min(1, r^4 + 2 coat_roughness^4). */
SS_FN float openpbr_specular_roughness(const Material* m) {
#if BRDF_FEATURE_COAT
    if (m->coat_weight > 0.0f)
        return mix(m->roughness, pow(fmin(1.0f, 2.0f * sqr(sqr(m->coat_roughness)) + sqr(sqr(m->roughness))), 0.25f), m->coat_weight);
#endif
    return m->roughness;
}

SS_FN OpenPbr openpbr_setup(const Material* m, GLOBAL_MEM const float* tables, float3 wo) {
    OpenPbr p;
    p.tables = tables;
    p.specular = openpbr_microfacet(openpbr_specular_roughness(m), m->anisotropic);
    p.coat = openpbr_microfacet(m->coat_roughness, m->coat_roughness_anisotropy);
    p.eta = dielectric_weighted_ior(m->ior, m->specular_weight);
    p.base = material_albedo(m) * m->base_weight;
    p.metal = m->metallic;
    p.opaque = (1.0f - m->metallic) * (1.0f - m->weight_transmission);
    p.glass = (1.0f - m->metallic) * m->weight_transmission;
    p.specular_smooth = microfacet_is_smooth(p.specular);
    p.coat_smooth = microfacet_is_smooth(p.coat);
    p.glass_smooth = p.specular_smooth || fabs(p.eta - 1.0f) < 1e-3f;
    p.metal_compensated = false;
    p.glass_compensated = false;
#if BRDF_FEATURE_ENERGY_COMPENSATION
    p.metal_compensated = m->energy_compensation != 0 && !p.specular_smooth;
    p.glass_compensated = m->energy_compensation != 0 && !p.glass_smooth;
#endif
    float mu_o = fabs(wo.z);
    p.fuzz_albedo = 0.0f;
    p.fuzz_normalisation = 1.0f;
#if BRDF_FEATURE_FUZZ
    if (m->fuzz_weight > 0.0f) {
        float e = openpbr_sheen_albedo(m->fuzz_roughness, mu_o);
        p.fuzz_normalisation = 1.0f / fmax(1.0f, e);
        p.fuzz_albedo = m->fuzz_weight * fmin(e, 1.0f);
    }
#endif
    p.coat_albedo = 0.0f;
    p.darkening = float3_splat(1.0f);
#if BRDF_FEATURE_COAT
    if (m->coat_weight > 0.0f) {
        p.coat_albedo = openpbr_specular_albedo(p.coat, m->coat_ior, mu_o);
        if (m->coat_darkening > 0.0f) {
            float k = 1.0f - (1.0f - openpbr_specular_average(p.coat, m->coat_ior)) / sqr(m->coat_ior);
            float3 d = float3_splat(1.0f - k) / (float3_splat(1.0f) - p.base * k);
            p.darkening = mix(float3_splat(1.0f), d, m->coat_darkening);
        }
    }
#endif
    /* the film changes the specular's albedo by about its change of the Fresnel reflectance (exactly,
     * for a smooth interface); a rough one sees facets at other angles too, where the film's
     * interference may reflect more: the largest change at mu_o and at the angles one alpha either
     * side of it. 0 without a film. */
    p.specular_albedo = float3_splat(0.0f); /* only the opaque dielectric has a layer under its specular */
    if (p.opaque > 0.0f) {
        float e_s = openpbr_specular_albedo(p.specular, p.eta, mu_o);
        float3 film = openpbr_film_change(m, p.eta, mu_o);
#if BRDF_FEATURE_THIN_FILM
        if (m->thin_film_weight > 0.0f && !p.specular_smooth) {
            float theta = acos(clamp(mu_o, 0.0f, 1.0f)), spread = atan(sqrt(p.specular.ax * p.specular.ay));
            film = fmax(film, fmax(openpbr_film_change(m, p.eta, cos(fmax(theta - spread, 0.0f))),
                                   openpbr_film_change(m, p.eta, cos(fmin(theta + spread, 0.5f * SS_PI)))));
        }
#endif
        float3 e_film = clamp(float3_splat(e_s) + film, 0.0f, 1.0f);
        p.specular_albedo = float3_from_array(m->specular_color) * e_film;
    }
    return p;
}

/* The coat's transmittance along the refracted path of w, one way: coat_color^(1 / (2 mu_t)). */
SS_FN float3 openpbr_coat_transmittance(const Material* m, float3 w) {
    float mu_t = safe_sqrt(1.0f - (1.0f - w.z * w.z) / sqr(m->coat_ior));
    float e = 0.5f / fmax(mu_t, 1e-4f);
    return make_float3(pow(m->coat_color[0], e), pow(m->coat_color[1], e), pow(m->coat_color[2], e));
}

/* What reaches the base through fuzz and coat from wo and back to wi (wi below: out of the coat once). */
SS_FN float3 openpbr_through_top(const Material* m, const OpenPbr* p, float3 wo, float3 wi) {
    float3 t = float3_splat(1.0f - p->fuzz_albedo);
#if BRDF_FEATURE_COAT
    if (m->coat_weight > 0.0f) {
        float3 path = openpbr_coat_transmittance(m, wo);
        if (wi.z > 0.0f) path = path * openpbr_coat_transmittance(m, wi);
        t = t * ((1.0f - m->coat_weight) + m->coat_weight * (1.0f - p->coat_albedo) * path * p->darkening);
    }
#endif
    return t;
}

/* The continuous part of the base, both directions above the surface, without the layers over it. */
SS_FN float3 openpbr_base_reflection(const Material* m, const OpenPbr* p, float3 wo, float3 wi) {
    float3 f = float3_splat(0.0f);
    float wo_h;
    float shape = microfacet_reflection_shape(p->specular, wo, wi, &wo_h);
    if (p->metal > 0.0f) {
        if (!p->specular_smooth) f += openpbr_metal_fresnel(m, p->base, wo_h) * (p->metal * shape);
#if BRDF_FEATURE_ENERGY_COMPENSATION
        if (p->metal_compensated)
            f += multiple_scattering_fresnel(p->base, microfacet_energy_average(p->specular, p->tables)) *
                 (p->metal * m->specular_weight * multiple_scattering_eval(p->specular, p->tables, wo, wi));
#endif
    }
    if (p->opaque > 0.0f) {
        if (!p->specular_smooth)
            f += float3_from_array(m->specular_color) * openpbr_specular_fresnel(m, p->eta, wo_h) * (p->opaque * shape);
        float3 below = (float3_splat(1.0f) - p->specular_albedo) * p->opaque;
        float3 under = float3_splat(0.0f);
#if BRDF_FEATURE_DIFFUSE
        under += eon_brdf(p->base, m->base_diffuse_roughness, wo, wi) * (1.0f - m->subsurface);
#endif
#if BRDF_FEATURE_SUBSURFACE
        if (m->subsurface > 0.0f)
            under += float3_from_array(m->subsurface_color) * (m->subsurface * henyey_greenstein_subsurface_brdf(wo, wi, m->subsurface_asymmetry));
#endif
        f += below * under;
    }
    return f;
}

/* The transmissive dielectric's continuous part for any pair of sides. */
SS_FN float3 openpbr_glass(const Material* m, const OpenPbr* p, float3 wo, float3 wi) {
#if BRDF_FEATURE_TRANSMISSION
    if (p->glass > 0.0f && !p->glass_smooth)
        return float3_from_array(m->transmission_color) * (p->glass * dielectric_lobe_eval(p->specular, p->eta, p->glass_compensated, wo, wi));
#endif
    return float3_splat(0.0f);
}

SS_FN float3 openpbr_eval_setup(const Material* m, const OpenPbr* p, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f)) return wo.z < 0.0f ? openpbr_glass(m, p, wo, wi) : float3_splat(0.0f);
    float3 f = float3_splat(0.0f);
#if BRDF_FEATURE_FUZZ
    if (m->fuzz_weight > 0.0f && wi.z > 0.0f)
        f += float3_from_array(m->fuzz_color) * (m->fuzz_weight * p->fuzz_normalisation * sheen_eval(m->fuzz_roughness, wo, wi));
#endif
#if BRDF_FEATURE_COAT
    if (m->coat_weight > 0.0f && wi.z > 0.0f && !p->coat_smooth)
        f += (1.0f - p->fuzz_albedo) * m->coat_weight * dielectric_reflection_eval(p->coat, m->coat_ior, wo, wi);
#endif
    float3 base = openpbr_glass(m, p, wo, wi);
    if (wi.z > 0.0f) base += openpbr_base_reflection(m, p, wo, wi);
    return f + openpbr_through_top(m, p, wo, wi) * base;
}

/* Probabilities of the sampling strategies at wo, each in proportion to an estimate of what its lobes
 * reflect, with a floor that keeps every lobe that can be non-zero sampleable: cosine-weighted (fuzz,
 * diffuse, the metal's multiple scattering), Henyey-Greenstein (subsurface), the coat's visible
 * normals or mirror, the metal's and the specular's (one microfacet distribution), the glass. */
typedef struct OpenPbrChoice {
    float cosine, subsurface, coat, metal, specular, glass;
} OpenPbrChoice;

#define OPENPBR_CHOICE_FLOOR 1e-3f

SS_FN OpenPbrChoice openpbr_choice(const Material* m, const OpenPbr* p, float3 wo) {
    OpenPbrChoice c;
    c.cosine = c.subsurface = c.coat = c.metal = c.specular = c.glass = 0.0f;
    if (!(wo.z > 0.0f)) {
        c.glass = p->glass > 0.0f ? 1.0f : 0.0f;
        return c;
    }
    float3 mirror = make_float3(-wo.x, -wo.y, wo.z);
    float under = mean3(openpbr_through_top(m, p, wo, mirror));
    float below = p->opaque * (1.0f - mean3(p->specular_albedo));
#if BRDF_FEATURE_FUZZ
    if (m->fuzz_weight > 0.0f) c.cosine += p->fuzz_albedo * mean3(float3_from_array(m->fuzz_color)) + OPENPBR_CHOICE_FLOOR * m->fuzz_weight;
#endif
#if BRDF_FEATURE_COAT
    if (m->coat_weight > 0.0f) c.coat = (1.0f - p->fuzz_albedo) * m->coat_weight * p->coat_albedo + OPENPBR_CHOICE_FLOOR * m->coat_weight;
#endif
#if BRDF_FEATURE_DIFFUSE
    if (m->subsurface < 1.0f) c.cosine += under * below * (1.0f - m->subsurface) * (mean3(p->base) + OPENPBR_CHOICE_FLOOR);
#endif
#if BRDF_FEATURE_SUBSURFACE
    if (m->subsurface > 0.0f) c.subsurface = under * below * m->subsurface * (mean3(float3_from_array(m->subsurface_color)) + OPENPBR_CHOICE_FLOOR);
#endif
    if (p->metal > 0.0f) {
        c.metal = under * p->metal * (mean3(openpbr_metal_fresnel(m, p->base, wo.z)) + OPENPBR_CHOICE_FLOOR);
#if BRDF_FEATURE_ENERGY_COMPENSATION
        if (p->metal_compensated)
            c.cosine += under * p->metal * m->specular_weight * mean3(multiple_scattering_fresnel(p->base, microfacet_energy_average(p->specular, p->tables))) *
                        multiple_scattering_albedo(p->specular, p->tables, wo);
#endif
    }
    if (p->opaque > 0.0f) c.specular = under * p->opaque * (mean3(p->specular_albedo) + OPENPBR_CHOICE_FLOOR);
#if BRDF_FEATURE_TRANSMISSION
    if (p->glass > 0.0f) c.glass = under * p->glass * (mean3(float3_from_array(m->transmission_color)) + OPENPBR_CHOICE_FLOOR);
#endif
    float sum = c.cosine + c.subsurface + c.coat + c.metal + c.specular + c.glass;
    if (!(sum > 0.0f)) return c;
    c.cosine /= sum;
    c.subsurface /= sum;
    c.coat /= sum;
    c.metal /= sum;
    c.specular /= sum;
    c.glass /= sum;
    return c;
}

SS_FN float openpbr_pdf_setup(const Material* m, const OpenPbr* p, OpenPbrChoice c, float3 wo, float3 wi) {
    float pdf = 0.0f;
    if (wo.z > 0.0f && wi.z > 0.0f) {
        pdf += c.cosine * cosine_hemisphere_pdf(wi.z);
#if BRDF_FEATURE_SUBSURFACE
        if (c.subsurface > 0.0f) pdf += c.subsurface * henyey_greenstein_subsurface_pdf(wo, wi, m->subsurface_asymmetry);
#endif
        if (c.coat > 0.0f && !p->coat_smooth) pdf += c.coat * microfacet_reflection_pdf(p->coat, wo, wi);
        if (c.metal + c.specular > 0.0f && !p->specular_smooth) pdf += (c.metal + c.specular) * microfacet_reflection_pdf(p->specular, wo, wi);
    }
#if BRDF_FEATURE_TRANSMISSION
    if (c.glass > 0.0f && !p->glass_smooth) pdf += c.glass * dielectric_lobe_pdf(p->specular, p->eta, p->glass_compensated, wo, wi);
#endif
    return pdf;
}

SS_FN float3 openpbr_eval(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    OpenPbr p = openpbr_setup(m, tables, wo);
    return openpbr_eval_setup(m, &p, wo, wi);
}

SS_FN float openpbr_pdf(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 wi) {
    OpenPbr p = openpbr_setup(m, tables, wo);
    return openpbr_pdf_setup(m, &p, openpbr_choice(m, &p, wo), wo, wi);
}

/* A delta lobe's sample: weight (what it reflects towards wi) and the probability it was picked with. */
SS_FN BsdfSample openpbr_delta_sample(float3 wi, float3 weight, float probability, int flags) {
    BsdfSample s = bsdf_sample_failed();
    if (wi.z == 0.0f || !(probability > 0.0f)) return s;
    s.wi = wi;
    s.f = weight / fabs(wi.z);
    s.pdf = probability;
    s.flags = flags | BSDF_DELTA;
    return s;
}

SS_FN BsdfSample openpbr_sample(const Material* m, GLOBAL_MEM const float* tables, float3 wo, float3 u) {
    OpenPbr p = openpbr_setup(m, tables, wo);
    OpenPbrChoice c = openpbr_choice(m, &p, wo);
    BsdfSample s = bsdf_sample_failed();
    float3 mirror = make_float3(-wo.x, -wo.y, wo.z);
    float3 wi;
    float uc = u.x;
    if (uc < c.cosine) {
        wi = square_to_cosine_hemisphere(u.y, u.z);
    } else if ((uc -= c.cosine) < c.subsurface) {
#if BRDF_FEATURE_SUBSURFACE
        wi = henyey_greenstein_subsurface_sample(wo, m->subsurface_asymmetry, u.y, u.z);
#else
        return s;
#endif
    } else if ((uc -= c.subsurface) < c.coat) {
        if (p.coat_smooth)
            return openpbr_delta_sample(mirror, float3_splat((1.0f - p.fuzz_albedo) * m->coat_weight * fresnel_dielectric(wo.z, m->coat_ior)), c.coat,
                                        BSDF_REFLECTION);
        if (!microfacet_reflection_sample_direction(p.coat, wo, u.y, u.z, &wi)) return s;
    } else if ((uc -= c.coat) < c.metal + c.specular) {
        if (p.specular_smooth) {
            float3 top = openpbr_through_top(m, &p, wo, mirror);
            if (uc < c.metal) return openpbr_delta_sample(mirror, top * openpbr_metal_fresnel(m, p.base, wo.z) * p.metal, c.metal, BSDF_REFLECTION);
            return openpbr_delta_sample(mirror, top * float3_from_array(m->specular_color) * openpbr_specular_fresnel(m, p.eta, wo.z) * p.opaque,
                                        c.specular, BSDF_REFLECTION);
        }
        if (!microfacet_reflection_sample_direction(p.specular, wo, u.y, u.z, &wi)) return s;
    } else if ((uc -= c.metal + c.specular) < c.glass) {
#if BRDF_FEATURE_TRANSMISSION
        float u_interface = fmin(uc / c.glass, 0.99999994f);
        if (p.glass_smooth) {
            s = smooth_dielectric_sample(p.eta, wo, u_interface);
            if (s.flags == 0) return s;
            float3 top = wo.z > 0.0f ? openpbr_through_top(m, &p, wo, s.wi) : float3_splat(1.0f);
            s.f = s.f * top * float3_from_array(m->transmission_color) * p.glass;
            s.pdf *= c.glass;
            return s;
        }
        if (!dielectric_lobe_sample_direction(p.specular, p.eta, p.glass_compensated, wo, u_interface, u.y, u.z, &wi)) return s;
#else
        return s;
#endif
    } else {
        return s;
    }
    s.pdf = openpbr_pdf_setup(m, &p, c, wo, wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.wi = wi;
    s.f = openpbr_eval_setup(m, &p, wo, wi);
    s.flags = same_hemisphere(wo, wi) ? BSDF_REFLECTION : BSDF_TRANSMISSION;
    return s;
}

#endif
