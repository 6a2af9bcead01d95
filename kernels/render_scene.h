/* What an integrator reads of the scene besides its distance field (which is compiled in): the
 * material slots, what each slot emits, the lights with their selection distribution, and the
 * environment. Buffers and kernel arguments, not source: a material, a light's power or the
 * environment's rotation and exposure change without a kernel build. */
#ifndef KERNELS_RENDER_SCENE_H
#define KERNELS_RENDER_SCENE_H

#include "single_source/vocabulary.h"
#include "brdf/material.h"
#include "ibl/environment.h"
#include "kernels/lights/environment_light.h"
#include "kernels/lights/light.h"

/* emission[slot].w: the slot emits nothing; it emits and absorbs what reaches it (a black emitter,
 * the path ends there); it emits and scatters by its material too (a reflecting emitter); its
 * material emits (brdf/emission.h: an emissive openpbr material on any shape, on its outer side
 * only, which no light sample can find: only the paths that hit it count it, with weight 1); or it
 * is a shadow catcher, which emits nothing and which the camera sees as the backdrop changed by
 * what the other objects do to its light (kernels/path_tracer.h, docs/environments.md). xyz holds
 * a sphere light's radiance; a material's emission is the material's (it depends on wo). */
#define EMISSION_CATCHER -1.0f
#define EMISSION_NONE 0.0f
#define EMISSION_ABSORBS 1.0f
#define EMISSION_SCATTERS 2.0f
#define EMISSION_SURFACE 3.0f

typedef struct RenderScene {
    GLOBAL_MEM const Material* materials; /* per material slot */
    GLOBAL_MEM const float* tables;       /* the BSDF's tables (brdf/bsdf_tables.h): energy, and the blocks measured materials name */
    GLOBAL_MEM const float4* emission;    /* per slot: xyz radiance, w one of EMISSION_* */
    GLOBAL_MEM const Light* lights;       /* the environment first when there is one */
    GLOBAL_MEM const float* light_cdf;    /* the selection distribution over the lights */
    GLOBAL_MEM const int* light_of_slot;  /* per slot: the light an emissive slot belongs to, else -1 */
    EnvironmentMap env;
    EnvironmentBuffers env_buffers;
} RenderScene;

/* The scene from its buffers, as every integrator's kernel entry (kernels/<integrator>.cl) binds them and the
 * host renderer holds them. */
SS_FN RenderScene render_scene_make(GLOBAL_MEM const Material* materials, GLOBAL_MEM const float* tables, GLOBAL_MEM const float4* emission, GLOBAL_MEM const Light* lights,
                                    GLOBAL_MEM const float* light_cdf, GLOBAL_MEM const int* light_of_slot, EnvironmentMap env,
                                    GLOBAL_MEM const float4* env_texels, GLOBAL_MEM const AliasEntry* env_alias) {
    RenderScene scene;
    scene.materials = materials;
    scene.tables = tables;
    scene.emission = emission;
    scene.lights = lights;
    scene.light_cdf = light_cdf;
    scene.light_of_slot = light_of_slot;
    scene.env = env;
    scene.env_buffers.texels = env_texels;
    scene.env_buffers.alias = env_alias;
    return scene;
}

#endif
