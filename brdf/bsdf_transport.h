/* The BSDF as a subpath sees it: radiance transport (camera subpaths, the path tracer) or
 * importance transport (light subpaths of BDPT and the light tracer), after pbrt-v4's TransportMode.
 *
 * The lab's BSDFs are written in their flux-conserving form (docs/materials.md): refraction without
 * the 1/eta^2 radiance scaling. In radiance mode that scaling is applied here, to transmission only,
 * with eta' the index of the side wi lies in relative to wo's (pbrt-v4 DielectricBxDF); in
 * importance mode it is left out. For a path that enters and leaves a closed object the factors
 * cancel, which is why the path tracer can use the flux form as it is.
 *
 * A non-reciprocal model (dtoadq2017, docs/dtoadq2017.md) is evaluated with its arguments in the
 * order the adjoint demands: a light subpath arrives from wo and leaves along wi, so the light it
 * carries is what the model scatters from wo into wi, seen by a viewer at wi: the adjoint
 * f*(wo, wi) = f(wi, wo). Sampling still draws wi from the model's own sampler (any density is
 * fine: it is divided out), and only f is swapped.
 *
 * The material is one that material_clamped() returned (bsdf.h's *_clamped forms): the renderer
 * clamps its materials once when it takes them, not at every vertex. */
#ifndef BRDF_BSDF_TRANSPORT_H
#define BRDF_BSDF_TRANSPORT_H
#include "single_source/vocabulary.h"
#include "bsdf.h"

#define TRANSPORT_RADIANCE 0
#define TRANSPORT_IMPORTANCE 1

/* Whether the model's f(wo, wi) differs from f(wi, wo) (in reflection). */
SS_FN bool bsdf_is_reciprocal(const Material* m) { return m->model != BRDF_MODEL_DTOADQ2017; }

/* The radiance-mode scale of a transmitted pair: 1 / eta'^2, eta' = eta when wo is outside. */
SS_FN float bsdf_radiance_scale(const Material* m, float3 wo, float3 wi) {
    if (same_hemisphere(wo, wi) || !(m->ior > 0.0f)) return 1.0f;
    float etap = wo.z > 0.0f ? m->ior : 1.0f / m->ior;
    return 1.0f / (etap * etap);
}

SS_FN float3 bsdf_eval_mode(const Material* m, GLOBAL_MEM const float* measured, float3 wo, float3 wi, int mode) {
    if (mode == TRANSPORT_IMPORTANCE) return bsdf_is_reciprocal(m) ? bsdf_eval_clamped(m, measured, wo, wi) : bsdf_eval_clamped(m, measured, wi, wo);
    return bsdf_eval_clamped(m, measured, wo, wi) * bsdf_radiance_scale(m, wo, wi);
}

/* bsdf_sample() with f in the given mode; pdf and flags are the sampler's. */
SS_FN BsdfSample bsdf_sample_mode(const Material* m, GLOBAL_MEM const float* measured, float3 wo, float3 u, int mode) {
    BsdfSample b = bsdf_sample_clamped(m, measured, wo, u);
    if (b.flags == 0) return b;
    if (mode == TRANSPORT_RADIANCE) b.f = b.f * bsdf_radiance_scale(m, wo, b.wi);
    else if (!bsdf_is_reciprocal(m) && (b.flags & BSDF_DELTA) == 0) b.f = bsdf_eval_clamped(m, measured, b.wi, wo);
    return b;
}

#endif
