/* The settings every integrator kernel takes (kernels/path_tracer.cl, kernels/bdpt.cl,
 * kernels/march_packets.cl, and the host build of the same integrators, render/host_renderer.cpp):
 * plain 4-byte scalars only (and structs of them), so the struct has one layout on both sides and
 * travels as a kernel argument by value. */
#ifndef KERNELS_RENDER_SETTINGS_H
#define KERNELS_RENDER_SETTINGS_H
#include "single_source/vocabulary.h"
#include "sdf/march_settings.h"
#include "kernels/bdpt_settings.h"

/* How a path finds the lights (the environment, emissive spheres, point lights):
 *   BSDF:   only where a BSDF-sampled ray happens to reach one (point lights are then never found);
 *   LIGHTS: next-event estimation only: a light sample and a shadow ray at every vertex; BSDF-sampled
 *           rays count where they reach a light only after a delta event, which NEE cannot produce;
 *   MIS:    both, weighted by the power heuristic (Veach 1997), so each covers where the other is poor. */
#define LIGHT_SAMPLING_BSDF 0
#define LIGHT_SAMPLING_LIGHTS 1
#define LIGHT_SAMPLING_MIS 2

typedef struct RenderKernelSettings {
    int first_sample;   /* sample index of this launch's first sample (keys the random numbers) */
    int sample_count;   /* samples per pixel in this launch */
    int max_depth;      /* scattering events per path; 0 shows only what the camera sees directly */
    int roulette_depth; /* Russian roulette from this many scattering events on */
    int light_sampling; /* LIGHT_SAMPLING_* */
    int normal_method;  /* NORMAL_* of sdf/normals.h */
    float normal_step;  /* finite-difference step of the numerical normals, scene units */
    uint seed_lo, seed_hi;
    /* what changes of sdf/march.h's MarchSettings; the epsilons are march_settings_default()'s */
    int max_steps;
    float max_distance, over_relaxation, lipschitz;
    int light_count;      /* entries of the light array; the environment, when there is one, is entry 0 */
    /* what a camera ray that escapes sees (kernels/background.h); lighting is the environment's:
     * opacity scales it (0 hides it), and background_face_size > 0 reads a prefiltered copy of the
     * map of that face size, stored in the environment's texel buffer from texel background_texels on */
    float background_opacity;
    int background_face_size;
    int background_texels;
    BdptKernelSettings bdpt; /* the bidirectional kernels' own (kernels/bdpt_settings.h) */
    float surface_lo[3], surface_hi[3]; /* MarchSettings' surface box */
} RenderKernelSettings;

/* sdf/march.h's settings with what the render settings change; the epsilons stay the defaults. */
SS_FN MarchSettings render_march_settings(const RenderKernelSettings* settings) {
    MarchSettings march_settings = march_settings_default(settings->lipschitz);
    march_settings.max_steps = settings->max_steps;
    march_settings.max_distance = settings->max_distance;
    march_settings.over_relaxation = settings->over_relaxation;
    /* each entry by itself, not in a loop: PoCL keeps the settings of such a loop in memory for every
     * work-item of the wavefront's step (docs/render.md, "Code PoCL compiles well") */
    march_settings.surface_lo[0] = settings->surface_lo[0];
    march_settings.surface_lo[1] = settings->surface_lo[1];
    march_settings.surface_lo[2] = settings->surface_lo[2];
    march_settings.surface_hi[0] = settings->surface_hi[0];
    march_settings.surface_hi[1] = settings->surface_hi[1];
    march_settings.surface_hi[2] = settings->surface_hi[2];
    return march_settings;
}

#endif
