/* The preview kernel's settings, shared by kernels/preview.cl and its host (ibl/preview_renderer):
 * plain 4-byte scalars only, so the struct has one layout on both sides and travels as a kernel
 * argument by value. */
#ifndef KERNELS_PREVIEW_SETTINGS_H
#define KERNELS_PREVIEW_SETTINGS_H
#include "single_source/vocabulary.h"

#define IBL_SAMPLING_BRDF 0
#define IBL_SAMPLING_ENV 1
#define IBL_SAMPLING_MIS 2

typedef struct PreviewKernelSettings {
    int first_sample;   /* sample index of this launch's first sample (keys the random numbers) */
    int sample_count;   /* samples per pixel in this launch */
    int max_depth;      /* scattering events per path; 0 shows only what the camera sees directly */
    int roulette_depth; /* Russian roulette from this many scattering events on */
    int strategy;       /* IBL_SAMPLING_* */
    int normal_method;  /* NORMAL_* of sdf/normals.h */
    float normal_step;  /* finite-difference step of the numerical normals, scene units */
    uint seed_lo, seed_hi;
    /* what changes of sdf/march.h's MarchSettings; the epsilons are march_settings_default()'s */
    int max_steps;
    float max_distance, over_relaxation, lipschitz;
} PreviewKernelSettings;

#endif
