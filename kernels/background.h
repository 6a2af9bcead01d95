/* The backdrop: what a camera ray that escapes the scene sees of the environment. It is a display
 * choice, not light: the environment lights the scene, and is seen in mirrors and through glass,
 * as it is, whatever the backdrop shows. Only the camera ray itself reads it -- not a ray after a
 * delta bounce -- so that a chrome ball and a glass model show the light they are lit by, and so
 * that every pixel whose camera ray hits a surface is the plain render's to the bit
 * (docs/environments.md, "Background").
 *
 * settings->background_opacity scales it (0: the lights kept, the backdrop hidden; the EXR's alpha
 * says how much of the pixel is backdrop). settings->background_face_size > 0 reads the prefiltered
 * map (ibl/background_blur.hpp) stored after the environment's own texels, from texel
 * settings->background_texels, with the same rotation and intensity; 0 reads the environment's own
 * texels. Either way the lookup is bilinear between texel centres, so the backdrop shows no texels. */
#ifndef KERNELS_BACKGROUND_H
#define KERNELS_BACKGROUND_H

#include "single_source/vocabulary.h"
#include "ibl/environment.h"
#include "kernels/render_scene.h"
#include "kernels/render_settings.h"

SS_FN float3 background_radiance(const RenderKernelSettings* settings, const RenderScene* scene, float3 direction) {
    EnvironmentMap map = scene->env;
    GLOBAL_MEM const float4* texels = scene->env_buffers.texels;
    if (settings->background_face_size > 0) {
        map.face_size = settings->background_face_size;
        texels += settings->background_texels;
    }
    return settings->background_opacity * environment_radiance_filtered(&map, texels, direction);
}

#endif
