/* The 2017 write-up's BRDF (section 6 of DTOADQ-writeup), kept as a named model so the lab can
 * show where it fails. Reconstructed from the write-up's fragments, flaws included on purpose
 * (docs/dtoadq2017.md lists them): a "Fresnel" that mixes albedo in and falls towards grazing,
 * a Smith term pairing N.V with H.L and missing a square, a Hyper-Cauchy D on the angle between
 * H and L, a Henyey-Greenstein term with 1/pi, and a final clamp to [0, 1].
 * It is sampled cosine-weighted, so estimates of it are unbiased and its failures are its own. */
#ifndef BRDF_DTOADQ2017_MODEL_H
#define BRDF_DTOADQ2017_MODEL_H
#include "bsdf_sample.h"
#include "single_source/vocabulary.h"
#include "fresnel.h"
#include "material.h"
#include "warp.h"

/* Heitz's height-correlated term as the 2017 kernel wrote it: alpha where alpha^2 belongs. */
SS_FN float dtoadq2017_smith(float cos_a, float cos_b, float alpha) {
    return cos_a * sqrt(cos_b * cos_b * (1.0f - alpha) + alpha);
}

/* Butler's Hyper-Cauchy, width s and shape g, evaluated at the angle it was handed. */
SS_FN float dtoadq2017_hyper_cauchy(float cos_angle, float s, float g) {
    float c2 = cos_angle * cos_angle;
    float tan2 = (1.0f - c2) / c2;
    return (g - 1.0f) * pow(2.0f, g - 1.0f) / (SS_PI * s * s * c2 * c2 * pow(2.0f + tan2 / (s * s), g));
}

SS_FN float3 dtoadq2017_eval(const Material* m, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return float3_splat(0.0f);
    float3 albedo = material_albedo(m);
    float3 h = normalize(wo + wi);
    float cos_nl = wi.z, cos_nv = wo.z;
    float cos_hl = dot(h, wi), cos_hv = dot(h, wo);
    /* "Fresnel": Schlick weights at L and V around a normal value F0 * cos^2(H.L) */
    float fresnel_l = schlick_weight(cos_nl), fresnel_v = schlick_weight(cos_nv);
    float f0 = m->fresnel * m->metallic;
    float fresnel_d90 = f0 * cos_hl * cos_hl;
    float3 fresnel = (1.0f - f0) * albedo + float3_splat(mix(1.0f, fresnel_d90, fresnel_l) * mix(1.0f, fresnel_d90, fresnel_v));
    /* geometry */
    float param = sqr(0.5f + sqr(m->roughness));
    float aspect = sqrt(1.0f - m->anisotropic * 0.9f);
    float ax = param / aspect, ay = param * aspect;
    float ggx_nv = dtoadq2017_smith(cos_hl, cos_nv, ax);
    float ggx_hl = dtoadq2017_smith(cos_nv, cos_hl, ay);
    float geometry = 0.5f / (ggx_nv * ax + ggx_hl * ay);
    /* distribution on the angle between H and L; width roughness, shape hc_shape */
    float distribution = dtoadq2017_hyper_cauchy(cos_hl, fmax(m->roughness, 1e-3f), m->hc_shape);
    float3 microfacet = fresnel * (geometry * distribution / (4.0f * cos_hv * fmax(cos_nl, cos_nv)));
    /* diffuse: sqrt(albedo)/pi, blended towards the half-vector Henyey-Greenstein retro term */
    float3 diffuse = make_float3(sqrt(albedo.x), sqrt(albedo.y), sqrt(albedo.z)) * SS_INV_PI;
    float r = (-0.3f + 1.3f * m->roughness) * cos_hv;
    float scale = (1.0f - m->metallic) * 5.0f;
    float rr = scale * (1.0f - r * r) * SS_INV_PI / pow(1.0f + r * r - 2.0f * r * cos_hl, 1.5f);
    float3 retro = diffuse * (rr * (fresnel_l + fresnel_v + fresnel_l * fresnel_v * rr));
    diffuse = mix(diffuse, retro, m->subsurface);
    float3 f = diffuse + microfacet;
    /* the 2017 kernel's final clamp; a NaN became 0 there */
    f.x = f.x != f.x ? 0.0f : clamp(f.x, 0.0f, 1.0f);
    f.y = f.y != f.y ? 0.0f : clamp(f.y, 0.0f, 1.0f);
    f.z = f.z != f.z ? 0.0f : clamp(f.z, 0.0f, 1.0f);
    return f;
}

SS_FN float dtoadq2017_pdf(float3 wo, float3 wi) {
    return wo.z > 0.0f ? cosine_hemisphere_pdf(wi.z) : 0.0f;
}

SS_FN BsdfSample dtoadq2017_sample(const Material* m, float3 wo, float3 u) {
    BsdfSample s = bsdf_sample_failed();
    if (!(wo.z > 0.0f)) return s;
    s.wi = square_to_cosine_hemisphere(u.y, u.z);
    s.pdf = dtoadq2017_pdf(wo, s.wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.f = dtoadq2017_eval(m, wo, s.wi);
    s.flags = BSDF_REFLECTION;
    return s;
}

#endif
