/* What only the bidirectional kernels (kernels/bdpt.h) read: their part of the render settings, and
 * their connection strategies. Strategy (s, t) joins s light-subpath vertices to t camera-subpath
 * vertices. Which of them a render adds up is a mask of STRATEGY_* (BdptKernelSettings.strategies):
 * bdpt takes them all, the light tracer `lt` only t = 1 (docs/bdpt.md; each integrator's mask is its
 * entry of render/integrator.cpp). */
#ifndef KERNELS_BDPT_SETTINGS_H
#define KERNELS_BDPT_SETTINGS_H
#include "single_source/vocabulary.h"

#define STRATEGY_S0 1      /* s = 0: the camera subpath reaches a light */
#define STRATEGY_S1 2      /* s = 1, t >= 2: a light sample joined to a camera vertex */
#define STRATEGY_S2 4      /* s >= 2, t >= 2: two subpath vertices joined by a visibility march */
#define STRATEGY_T1 8      /* t = 1: a light-subpath vertex joined to the lens, splatted */
#define STRATEGY_ALL 15

/* The most vertices of a bidirectional path (max_depth + 2): the size of the host build's private
 * vertex arrays (kernels/bdpt_vertex.h); an OpenCL build sizes them to its own max_vertices. */
#define BDPT_VERTEX_LIMIT 64

/* A light-vertex cache's vertex (kernels/bdpt_cache.h) takes at most this many bytes on any
 * device (the OpenCL build's PathVertex, its float3s of 16 bytes, is 128; kernels/bdpt.cl
 * checks it): the renderers size the cache's vertex buffer with it. */
#define BDPT_CACHE_VERTEX_BYTES 128

#define MIS_BALANCE 0
#define MIS_POWER 1

/* Plain 4-byte scalars only: a member of RenderKernelSettings, which travels by value. */
typedef struct BdptKernelSettings {
    int max_vertices;     /* s + t at most: max_depth + 2, the lens, max_depth scattering events and the light */
    int strategies;       /* STRATEGY_* mask */
    int mis_heuristic;    /* MIS_* */
    int single_strategy;  /* >= 0: add only the strategy of this bdpt_strategy_code, weighted by the mask's MIS
                             (--strategies DIR); -1: every strategy of the mask */
    int unweighted;       /* 1: with single_strategy, its contribution without the MIS weight */
    float scene_center[3]; /* the sphere holding the scene: the disk environment light paths start on */
    float scene_radius;
    /* How many samples of a strategy one camera subpath gets, relative to s <= 1's one each: the
     * factors n_i of the MIS weights n_i p_i / sum_j n_j p_j (bdpt_strategy_samples). Both 1 for the
     * per-pixel kernel (one light subpath per camera subpath); the light-vertex cache
     * (kernels/bdpt_cache.h) has N_L / N_pixels light subpaths per camera subpath for t = 1 and
     * M / (mean connectable vertices per light subpath) connections of each camera vertex to a
     * given light vertex for s >= 2, t >= 2 (docs/bdpt.md, "The light-vertex cache"). */
    float light_tracing_samples;
    float connection_samples;
    /* Connection roulette: a connection of MIS weight w below this traces its visibility march
     * with probability w / connection_roulette and counts 1 / that probability (bdpt_connect);
     * 0: every connection of nonzero weight traces it. */
    float connection_roulette;
    /* Vertex merging (vcm, kernels/vcm.h): this sample index's merge radius r_i (0: no merging),
     * the first sample's r_0 it shrinks from (render/vcm.cpp), and merge_samples = N_L pi r_i^2,
     * the merging strategy's count n_VM p_VM / p of the MIS weights (kernels/bdpt_mis.h). */
    float merge_radius;
    float merge_radius0;
    float merge_samples;
} BdptKernelSettings;

/* Whether strategy (s, t) belongs to the mask. */
SS_FN bool bdpt_strategy_enabled(int mask, int s, int t) {
    if (t == 1) return (mask & STRATEGY_T1) != 0;
    if (t < 1) return false; /* the lens is never hit */
    if (s == 0) return (mask & STRATEGY_S0) != 0;
    if (s == 1) return (mask & STRATEGY_S1) != 0;
    return (mask & STRATEGY_S2) != 0;
}

/* n_i of strategy (s, t): see BdptKernelSettings.light_tracing_samples. */
SS_FN float bdpt_strategy_samples(const BdptKernelSettings* bdpt, int s, int t) {
    if (t == 1) return bdpt->light_tracing_samples;
    return s >= 2 ? bdpt->connection_samples : 1.0f;
}

/* One number per strategy, s * (BDPT_VERTEX_LIMIT + 1) + t, distinct for every (s, t) a path can
 * have (s + t <= BDPT_VERTEX_LIMIT, so t <= BDPT_VERTEX_LIMIT; t = 0 never runs):
 * BdptKernelSettings.single_strategy names the one strategy a render adds alone, and 1 + the code
 * is the random-number stream of the strategy's own light and lens samples. */
SS_FN int bdpt_strategy_code(int s, int t) { return s * (BDPT_VERTEX_LIMIT + 1) + t; }

#endif
