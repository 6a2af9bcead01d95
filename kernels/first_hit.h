/* First-hit AOVs: what one camera ray of a pixel's sample finds at its first surface, for the
 * EXR's albedo, normal and depth layers (render/first_hit_aovs.cpp averages them over the film's
 * samples) and its material slot layer (the slot of the pixel's first sample, as Cycles writes its
 * material index on sample 0). The camera ray is the one the sample's path began with (camera_pixel_ray from the
 * same random stream), so the AOVs cover the pixel as its radiance does.
 *
 * Albedo is the directional albedo of the material seen, estimated by FIRST_HIT_ALBEDO_SAMPLES BSDF
 * samples: the mean of their weights f |cos| / pdf, whose expectation is the fraction of light the
 * surface reflects toward the viewer. One sample would do for the mean over many, but a material
 * of several lobes weighs each sample by the lobe it drew, and the display denoiser multiplies its
 * filtered illumination by this albedo again: at one or two samples per pixel its noise would come
 * straight back into the image. That is what Open Image Denoise asks of its albedo guide (the diffuse colour of a
 * matte surface, the Fresnel colour of a metal, about 1 for glass) and what Blender's denoising
 * albedo pass holds; a Lambert surface's weight is exactly its albedo. The base colour alone would
 * call a black-based metal black and a clear dielectric its tint. Needs the scene declared
 * before it, as kernels/path.h does. */
#ifndef KERNELS_FIRST_HIT_H
#define KERNELS_FIRST_HIT_H

#include "single_source/vocabulary.h"
#include "brdf/bsdf.h"
#include "kernels/camera.h"
#include "kernels/path.h"
#include "kernels/render_scene.h"
#include "kernels/rng.h"

#define FIRST_HIT_ALBEDO_SAMPLES 8

typedef struct FirstHit {
    float3 albedo; /* estimate of the directional albedo (FIRST_HIT_ALBEDO_SAMPLES samples); 0 where the ray escapes */
    float3 normal; /* world-space shading normal, facing the camera; 0 where the ray escapes */
    float depth;   /* distance along the camera ray; 0 where it escapes (as Mitsuba's depth AOV) */
    float coverage; /* 1 where the ray hits a surface, 0 where it sees the backdrop: the EXR's alpha */
    int slot;       /* the material slot seen; -1 where the ray escapes */
} FirstHit;

SS_FN FirstHit first_hit_sample(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int pixel, int sample) {
    FirstHit h;
    h.albedo = float3_splat(0.0f);
    h.normal = float3_splat(0.0f);
    h.depth = 0.0f;
    h.coverage = 0.0f;
    h.slot = -1;
    MarchSettings march_settings = render_march_settings(settings);
    Rng rng = rng_make((uint)pixel, (uint)sample, settings->seed_lo, settings->seed_hi);
    float3 origin, direction;
    camera_pixel_ray(camera, pixel, &rng, &origin, &direction);
    PathCounters counters = path_counters_zero();
    MarchResult r = trace_ray(origin, direction, march_settings, &counters);
    if (r.status != MARCH_HIT) return h;
    SurfaceHit hit = surface_hit(settings, march_settings, origin, direction, r.t, scene_distance(origin) < 0.0f);
    h.normal = hit.frame.n;
    h.depth = r.t;
    h.coverage = scene->emission[hit.slot].w == EMISSION_CATCHER ? 0.0f : 1.0f; /* a shadow catcher shows the backdrop */
    h.slot = hit.slot;
    Material m = scene->materials[hit.slot];
    for (int i = 0; i < FIRST_HIT_ALBEDO_SAMPLES; ++i) {
        float4 u = rng_next4(&rng);
        BsdfSample b = bsdf_sample_clamped(&m, scene->tables, hit.wo, make_float3(u.x, u.y, u.z));
        if (b.flags != 0) h.albedo += b.f * (fabs(b.wi.z) / b.pdf);
    }
    h.albedo *= 1.0f / (float)FIRST_HIT_ALBEDO_SAMPLES;
    return h;
}

#endif
