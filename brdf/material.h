/* Material parameters as every BRDF consumer sees them (host, lobe plots, kernels).
 * Plain scalars only, so the struct has the same layout in C++ and OpenCL C and can be copied
 * into a buffer as is. Meanings and ranges: docs/materials.md; the range table lives in
 * brdf/host/parameters.cpp and the loader enforces it. */
#ifndef BRDF_MATERIAL_H
#define BRDF_MATERIAL_H
#include "single_source/vocabulary.h"

#define BRDF_MODEL_LAB 0        /* the physically plausible default model */
#define BRDF_MODEL_DTOADQ2017 1 /* the 2017 write-up's formulas, kept for comparison */
#define BRDF_MODEL_MEASURED 2   /* a MERL table (brdf/measured.h); measured_offset says where it lies */
#define BRDF_MODEL_OPENPBR 3    /* OpenPBR Surface 1.1's layers (brdf/openpbr_model.h) */

#define BRDF_DISTRIBUTION_GGX 0
#define BRDF_DISTRIBUTION_HYPER_CAUCHY 1

typedef struct Material {
    float albedo[3];            /* linear RGB reflectance / tint */
    float roughness;            /* perceptual; microfacet alpha = roughness^2 */
    float metallic;             /* 0 dielectric .. 1 conductor */
    float fresnel;              /* reflectance at normal incidence of the dielectric part */
    float subsurface;           /* diffuse lobe: 0 Lambert/Disney .. 1 Henyey-Greenstein single scattering */
    float subsurface_asymmetry; /* Henyey-Greenstein g; < 0 scatters back (retro-reflection) */
    float retroreflection;      /* diffuse lobe: 0 Lambert .. 1 Disney's diffuse Fresnel factor */
    float anisotropic;          /* 0 isotropic .. 1 strongest stretch along the tangent */
    float tangent_rotation;     /* radians, rotates the anisotropy tangent about the normal */
    float hc_shape;             /* Hyper-Cauchy shape g; 2 equals GGX, larger is lighter-tailed */
    float weight_diffuse;       /* lobe weights: relative, normalised by their sum */
    float weight_glossy;
    float weight_specular;
    float weight_transmission;
    float ior;                  /* index of refraction of the transmissive lobe */
    int model;                  /* BRDF_MODEL_* */
    int distribution;           /* BRDF_DISTRIBUTION_*, used by glossy and rough transmission */
    int energy_compensation;    /* 1: microfacet lobes get Kulla-Conty multiple scattering; 0: single scattering only */
    int measured_offset;        /* BRDF_MODEL_MEASURED: first float of its block in the measured-tables buffer */
    /* BRDF_MODEL_OPENPBR's inputs that have no field above; the others share one (base_color is albedo,
     * base_metalness metallic, specular_roughness roughness, specular_roughness_anisotropy anisotropic,
     * specular_ior ior, transmission_weight weight_transmission, subsurface_weight subsurface,
     * subsurface_scatter_anisotropy subsurface_asymmetry). Meanings: docs/materials.md. */
    float base_weight;
    float base_diffuse_roughness;
    float specular_weight;
    float specular_color[3];
    float transmission_color[3];
    float subsurface_color[3];
    float coat_weight;
    float coat_color[3];
    float coat_roughness;
    float coat_roughness_anisotropy;
    float coat_ior;
    float coat_darkening;
    float fuzz_weight;
    float fuzz_color[3];
    float fuzz_roughness;
    float thin_film_weight;
    float thin_film_thickness;  /* micrometres */
    float thin_film_ior;
    float emission_luminance;   /* nits; radiance emission_luminance emission_color (docs/materials.md, Emission) */
    float emission_color[3];
} Material;

SS_FN float3 material_albedo(const Material* m) { return make_float3(m->albedo[0], m->albedo[1], m->albedo[2]); }

/* Parameter ranges: the single source for the loader, the docs table, the sweeps and the clamp
 * below (which keeps a kernel defined even when handed an unchecked struct). */
#define BRDF_ASYMMETRY_MAX 0.95f
#define BRDF_HC_SHAPE_MIN 1.6f
#define BRDF_HC_SHAPE_MAX 16.0f
#define BRDF_IOR_MIN 1.0f
#define BRDF_IOR_MAX 3.0f
#define BRDF_THIN_FILM_THICKNESS_MAX 2.0f /* micrometres; thicker films average to their incoherent sum */
#define BRDF_EMISSION_LUMINANCE_MAX 1e6f  /* nits: a bright lamp's surface; OpenPBR's soft range ends at 1000 */

/* fmin(fmax()) rather than clamp(): it maps NaN to the lower bound instead of leaving it. */
SS_FN float clamp_param(float x, float lo, float hi) { return fmin(fmax(x, lo), hi); }

SS_FN Material material_clamped(const Material* in) {
    Material m = *in;
    for (int c = 0; c < 3; ++c) m.albedo[c] = clamp_param(m.albedo[c], 0.0f, 1.0f);
    m.roughness = clamp_param(m.roughness, 0.0f, 1.0f);
    m.metallic = clamp_param(m.metallic, 0.0f, 1.0f);
    m.fresnel = clamp_param(m.fresnel, 0.0f, 1.0f);
    m.subsurface = clamp_param(m.subsurface, 0.0f, 1.0f);
    m.subsurface_asymmetry = clamp_param(m.subsurface_asymmetry, -BRDF_ASYMMETRY_MAX, BRDF_ASYMMETRY_MAX);
    m.retroreflection = clamp_param(m.retroreflection, 0.0f, 1.0f);
    m.anisotropic = clamp_param(m.anisotropic, 0.0f, 1.0f);
    m.tangent_rotation = clamp_param(m.tangent_rotation, -2.0f * SS_PI, 2.0f * SS_PI);
    m.hc_shape = clamp_param(m.hc_shape, BRDF_HC_SHAPE_MIN, BRDF_HC_SHAPE_MAX);
    m.weight_diffuse = clamp_param(m.weight_diffuse, 0.0f, 1.0f);
    m.weight_glossy = clamp_param(m.weight_glossy, 0.0f, 1.0f);
    m.weight_specular = clamp_param(m.weight_specular, 0.0f, 1.0f);
    m.weight_transmission = clamp_param(m.weight_transmission, 0.0f, 1.0f);
    m.ior = clamp_param(m.ior, BRDF_IOR_MIN, BRDF_IOR_MAX);
    for (int c = 0; c < 3; ++c) {
        m.specular_color[c] = clamp_param(m.specular_color[c], 0.0f, 1.0f);
        m.transmission_color[c] = clamp_param(m.transmission_color[c], 0.0f, 1.0f);
        m.subsurface_color[c] = clamp_param(m.subsurface_color[c], 0.0f, 1.0f);
        m.coat_color[c] = clamp_param(m.coat_color[c], 0.0f, 1.0f);
        m.fuzz_color[c] = clamp_param(m.fuzz_color[c], 0.0f, 1.0f);
        m.emission_color[c] = clamp_param(m.emission_color[c], 0.0f, 1.0f);
    }
    m.base_weight = clamp_param(m.base_weight, 0.0f, 1.0f);
    m.base_diffuse_roughness = clamp_param(m.base_diffuse_roughness, 0.0f, 1.0f);
    m.specular_weight = clamp_param(m.specular_weight, 0.0f, 1.0f);
    m.coat_weight = clamp_param(m.coat_weight, 0.0f, 1.0f);
    m.coat_roughness = clamp_param(m.coat_roughness, 0.0f, 1.0f);
    m.coat_roughness_anisotropy = clamp_param(m.coat_roughness_anisotropy, 0.0f, 1.0f);
    m.coat_ior = clamp_param(m.coat_ior, BRDF_IOR_MIN, BRDF_IOR_MAX);
    m.coat_darkening = clamp_param(m.coat_darkening, 0.0f, 1.0f);
    m.fuzz_weight = clamp_param(m.fuzz_weight, 0.0f, 1.0f);
    m.fuzz_roughness = clamp_param(m.fuzz_roughness, 0.0f, 1.0f);
    m.thin_film_weight = clamp_param(m.thin_film_weight, 0.0f, 1.0f);
    m.thin_film_thickness = clamp_param(m.thin_film_thickness, 0.0f, BRDF_THIN_FILM_THICKNESS_MAX);
    m.thin_film_ior = clamp_param(m.thin_film_ior, BRDF_IOR_MIN, BRDF_IOR_MAX);
    m.emission_luminance = clamp_param(m.emission_luminance, 0.0f, BRDF_EMISSION_LUMINANCE_MAX);
    return m;
}

/* Whether a material emits light of its own: an openpbr material with emission_luminance and
 * emission_color above 0 (brdf/emission.h gives the radiance). The host switches the kernel's
 * emission code on by it (BRDF_FEATURE_EMISSION) and marks the slot's emission
 * (kernels/render_scene.h). */
SS_FN bool material_emits(const Material* m) {
    return m->model == BRDF_MODEL_OPENPBR && m->emission_luminance > 0.0f &&
           (m->emission_color[0] > 0.0f || m->emission_color[1] > 0.0f || m->emission_color[2] > 0.0f);
}

#endif
