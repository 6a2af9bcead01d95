/* The environment map as a light, through ibl/environment.h's importance sampler (texels drawn in
 * proportion to luminance times solid angle). The radiance is the nearest-texel lookup, the
 * piecewise-constant function that sampler's pdf matches, so radiance / pdf never mixes texels. */
#ifndef KERNELS_LIGHTS_ENVIRONMENT_LIGHT_H
#define KERNELS_LIGHTS_ENVIRONMENT_LIGHT_H
#include "single_source/vocabulary.h"
#include "ibl/environment.h"
#include "kernels/lights/light.h"

/* The environment's two buffers (ibl/environment.h): texels (radiance, and in w the texel's
 * probability, which environment_pdf reads) and the alias tables (which only the sampler reads). */
typedef struct EnvironmentBuffers {
    GLOBAL_MEM const float4* texels;
    GLOBAL_MEM const AliasEntry* alias;
} EnvironmentBuffers;

SS_FN LightSample environment_light_sample(const EnvironmentMap* env, EnvironmentBuffers b, float2 u) {
    LightSample s = light_sample_none();
    float pdf;
    float3 radiance;
    float3 wi = environment_sample_radiance(env, b.texels, b.alias, u.x, u.y, &pdf, &radiance);
    if (!(pdf > 0.0f)) return s;
    s.wi = wi;
    s.distance = LIGHT_INFINITE_DISTANCE;
    s.radiance = radiance;
    s.pdf = pdf;
    s.position = wi; /* a point at infinity: its direction */
    s.normal = -wi;
    return s;
}

SS_FN float environment_light_pdf(const EnvironmentMap* env, EnvironmentBuffers b, float3 wi) {
    return environment_pdf(env, b.texels, wi);
}

#endif
