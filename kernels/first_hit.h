/* First-hit AOVs: what one camera ray of a pixel's sample finds at its first surface, for the
 * EXR's albedo, normal and depth layers (render/first_hit_aovs.cpp averages them over the film's
 * samples) and its material slot layer (the slot of the pixel's first sample, as Cycles writes its
 * material index on sample 0). The camera ray is the one the sample's path began with (camera_pixel_ray from the
 * same random stream), so the AOVs cover the pixel as its radiance does.
 *
 * Albedo is the directional albedo of the material seen, estimated by one BSDF sample: its weight
 * f |cos| / pdf, whose mean over the samples is the fraction of light the surface reflects toward
 * the viewer. That is what Open Image Denoise asks of its albedo guide (the diffuse colour of a
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

typedef struct FirstHit {
    float3 albedo; /* one-sample estimate of the directional albedo; 0 where the ray escapes */
    float3 normal; /* world-space shading normal, facing the camera; 0 where the ray escapes */
    float depth;   /* distance along the camera ray; 0 where it escapes (as Mitsuba's depth AOV) */
    int slot;      /* the material slot seen; -1 where the ray escapes */
} FirstHit;

SS_FN FirstHit first_hit_sample(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, int pixel, int sample) {
    FirstHit h;
    h.albedo = float3_splat(0.0f);
    h.normal = float3_splat(0.0f);
    h.depth = 0.0f;
    h.slot = -1;
    MarchSettings march_settings = render_march_settings(settings);
    Rng rng = rng_make((uint)pixel, (uint)sample, settings->seed_lo, settings->seed_hi);
    float3 origin, direction;
    camera_pixel_ray(camera, pixel, &rng, &origin, &direction);
    PathCounters counters;
    counters.rays = 0u;
    counters.lost_rays = 0u;
    MarchResult r = trace_ray(origin, direction, march_settings, &counters);
    if (r.status != MARCH_HIT) return h;
    SurfaceHit hit = surface_hit(settings, march_settings, origin, direction, r.t, scene_distance(origin) < 0.0f);
    h.normal = hit.frame.n;
    h.depth = r.t;
    h.slot = hit.slot;
    Material m = scene->materials[hit.slot];
    float4 u = rng_next4(&rng);
    BsdfSample b = bsdf_sample_clamped(&m, scene->measured, hit.wo, make_float3(u.x, u.y, u.z));
    if (b.flags != 0) h.albedo = b.f * (fabs(b.wi.z) / b.pdf);
    return h;
}

#endif
