/* Choosing one light per next-event estimate, and the dispatch over light types.
 *
 * The host (render/light_set.cpp) builds a cdf of count + 1 floats over the lights: cdf[0] = 0,
 * cdf[count] = 1, light k chosen with probability cdf[k + 1] - cdf[k] (in proportion to its power,
 * or uniform; docs/lights.md). Sampling is ibl/distribution1d.h's one-dimensional sampler, so the
 * pmf is the difference of the very floats it compares with and a light of probability 0 is never
 * chosen. */
#ifndef KERNELS_LIGHTS_LIGHT_SELECTION_H
#define KERNELS_LIGHTS_LIGHT_SELECTION_H
#include "single_source/vocabulary.h"
#include "ibl/distribution1d.h"
#include "kernels/lights/area_light.h"
#include "kernels/lights/environment_light.h"
#include "kernels/lights/image_emitter.h"
#include "kernels/lights/light.h"
#include "kernels/lights/point_light.h"
#include "kernels/lights/sphere_light.h"

/* The kinds of light a kernel can meet, a bit (1 << LIGHT_*) each. The OpenCL renderer builds a
 * scene's kernel with its own lights' kinds (-DSCENE_LIGHT_TYPES, render/light_set.hpp), so the
 * samplers of kinds the scene lacks are not compiled: the sphere under an environment map spent
 * registers and code on sphere and point lights it never has. The host handles every kind. */
#ifndef SCENE_LIGHT_TYPES
#define SCENE_LIGHT_TYPES \
    ((1 << LIGHT_ENVIRONMENT) | (1 << LIGHT_SPHERE) | (1 << LIGHT_POINT) | (1 << LIGHT_RECT) | (1 << LIGHT_DISK) | (1 << LIGHT_IMAGE))
#endif
#define SCENE_HAS_LIGHT_TYPE(type) ((SCENE_LIGHT_TYPES >> (type)) & 1)

/* Whether rect or disk l shows an image (kernels/lights/image_emitter.h); never in a kernel built
 * for a scene without image emitters (the bit 1 << LIGHT_IMAGE of SCENE_LIGHT_TYPES). */
SS_FN bool light_has_image(const Light* l) { return SCENE_HAS_LIGHT_TYPE(LIGHT_IMAGE) && l->image > 0; }

/* The light for u in [0, 1), and its probability in *pmf; -1 (and *pmf = 0) without lights. */
SS_FN int select_light(GLOBAL_MEM const float* cdf, int count, float u, float* pmf) {
    if (count <= 0) {
        *pmf = 0.0f;
        return -1;
    }
    float offset;
    int k = distribution1d_sample(cdf, count, u, &offset);
    *pmf = distribution1d_probability(cdf, k);
    return k;
}

/* The probability with which select_light() chooses light `index`. */
SS_FN float light_selection_pmf(GLOBAL_MEM const float* cdf, int count, int index) {
    if (index < 0 || index >= count) return 0.0f;
    return distribution1d_probability(cdf, index);
}

/* A sample of light l from p (u: two uniform numbers; the point light uses none). */
SS_FN LightSample sample_light(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float2 u) {
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_SPHERE) && l->type == LIGHT_SPHERE) return sphere_light_sample(l, p, u);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_POINT) && l->type == LIGHT_POINT) return point_light_sample(l, p);
    if (light_has_image(l)) return image_emitter_sample(l, b, p, u);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_RECT) && l->type == LIGHT_RECT) return area_light_sample(l, p, u);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_DISK) && l->type == LIGHT_DISK) return area_light_sample(l, p, u);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_ENVIRONMENT) && l->type == LIGHT_ENVIRONMENT) return environment_light_sample(env, b, u);
    return light_sample_none();
}

/* The solid-angle density with which sample_light() from p returns the unit direction wi, for
 * weighting a BSDF sample that found this light (0 for a point light: no direction finds it). */
SS_FN float light_pdf(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float3 wi) {
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_SPHERE) && l->type == LIGHT_SPHERE) return sphere_light_pdf(l, p, wi);
    if (light_has_image(l)) return image_emitter_pdf(l, b, p, wi);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_RECT) && l->type == LIGHT_RECT) return area_light_pdf(l, p, wi);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_DISK) && l->type == LIGHT_DISK) return area_light_pdf(l, p, wi);
    if (SCENE_HAS_LIGHT_TYPE(LIGHT_ENVIRONMENT) && l->type == LIGHT_ENVIRONMENT) return environment_light_pdf(env, b, wi);
    return 0.0f; /* a point light */
}

/* Whether the light is a surface of the scene (an emitter: sphere, rect or disk), whose light
 * subpaths start at a point drawn by area. */
SS_FN bool light_is_surface(int type) { return type == LIGHT_SPHERE || type == LIGHT_RECT || type == LIGHT_DISK; }

/* For a surface light: the density per unit area with which its light subpaths start at its point
 * q (uniform, but by the texels' weights for an image), and a point drawn with it, with the outward
 * normal there (a rect's or disk's emitting side). */
SS_FN float light_area_pdf(const Light* l, EnvironmentBuffers b, float3 q) {
    if (light_has_image(l)) return image_emitter_area_pdf(l, b, q);
    return l->type == LIGHT_SPHERE ? sphere_light_area_pdf(l) : area_light_area_pdf(l);
}

SS_FN float3 light_sample_area(const Light* l, EnvironmentBuffers b, float2 u, float3* normal) {
    if (light_has_image(l)) {
        *normal = area_light_normal(l);
        return image_emitter_sample_point(l, b, u);
    }
    return l->type == LIGHT_SPHERE ? sphere_light_sample_area(l, u, normal) : area_light_sample_area(l, u, normal);
}

/* The radiance a surface light sends along the unit direction w from its point q: a sphere's Le on
 * either side, a rect's or disk's on its emitting side only (an image's texel at q). */
SS_FN float3 light_surface_radiance(const Light* l, EnvironmentBuffers b, float3 q, float3 w) {
    if (light_has_image(l)) return image_emitter_radiance(l, b, q, w);
    return l->type == LIGHT_SPHERE ? float3_from_array(l->emission) : area_light_radiance(l, w);
}

#endif
