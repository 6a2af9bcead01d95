/* Light a material emits of its own (OpenPBR's emission_luminance and emission_color), as the
 * integrators add it where a path reaches the surface. The emission lies under the coat and the
 * fuzz, as in OpenPBR, and leaves through them as the base's reflection does (brdf/openpbr_model.h):
 * the fuzz passes 1 - its albedo at mu_o, the coat 1 - E_coat(mu_o), its absorption along the
 * refracted path once (coat_color^(1 / (2 mu_t))) and its darkening, each mixed in by its weight.
 * It is emitted on the outer side only (wo.z > 0: the side the shading normal faces outside the
 * solid), as the layers are one-sided. Units: the renderer's radiance of white (1, 1, 1) is 1 nit,
 * so the radiance is emission_luminance emission_color (docs/materials.md, Emission). Only kernels
 * whose materials emit compile it (BRDF_FEATURE_EMISSION). */
#ifndef BRDF_EMISSION_H
#define BRDF_EMISSION_H
#include "single_source/vocabulary.h"
#include "features.h"
#include "material.h"
#if BRDF_FEATURE_EMISSION && BRDF_FEATURE_OPENPBR
#include "openpbr_model.h"
#endif

/* The radiance m (clamped, material_clamped) emits towards wo, in the local shading frame. */
SS_FN float3 material_emission_clamped(const Material* m, float3 wo) {
#if BRDF_FEATURE_EMISSION && BRDF_FEATURE_OPENPBR
    if (wo.z > 0.0f && material_emits(m)) {
        OpenPbr p = openpbr_setup(m, 0, wo); /* through the top layers: no lookup in the global tables */
        float3 below = make_float3(0.0f, 0.0f, -1.0f); /* the light leaves the layers once */
        return float3_from_array(m->emission_color) * (m->emission_luminance * openpbr_through_top(m, &p, wo, below));
    }
#else
    (void)m, (void)wo;
#endif
    return float3_splat(0.0f);
}

#endif
