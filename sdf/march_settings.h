/* What every march takes and reports: the settings of sphere tracing (sdf/march.h, one ray; and
 * sdf/march_lanes.h, a packet), their defaults, the hit threshold and the statuses. */
#ifndef SDF_MARCH_SETTINGS_H
#define SDF_MARCH_SETTINGS_H

#include "single_source/vocabulary.h"

#define MARCH_HIT 0
#define MARCH_MISS 1         /* the ray left max_distance */
#define MARCH_OUT_OF_STEPS 2 /* max_steps distance evaluations without a hit or a miss */

typedef struct MarchSettings {
    float epsilon_relative; /* hit when |d| / lipschitz < max(epsilon_min, epsilon_relative * t) */
    float epsilon_min;
    int max_steps;          /* distance evaluations */
    float max_distance;     /* along the ray, from the origin */
    /* non-0: a surface lies at max_distance (the ray's exact hit, sdf/exact/with_march.h), so the
     * march ends as a miss only once a step it has verified reaches it, never on an over-relaxed
     * step that leaps past it unchecked (sdf/march_lanes.h) */
    int surface_at_max_distance;
    float over_relaxation;  /* omega: 1 = plain sphere tracing; 1.2..1.6 Keinert et al. 2014 */
    float lipschitz;        /* distances are divided by this (the scene's bound, >= 1) */
    /* A box holding every surface (the scene compiler's surface box), -INFINITY / INFINITY where
     * the scene is unbounded: a ray that has left it sees nothing more (sdf/march_lanes.h) */
    float surface_lo[3], surface_hi[3];
} MarchSettings;

/* Defaults for scenes of a few units to a few tens of units across:
 *  - epsilon_relative 1e-4: the hit threshold grows with t like a pixel's footprint (1e-4 rad is
 *    about a pixel of a 60-degree 1000-pixel image), far above float rounding (~1e-7 t);
 *  - epsilon_min 1e-5: the threshold near the origin, where epsilon_relative * t vanishes;
 *  - max_steps 256: plain tracing reaches most surfaces in tens of steps; rays grazing a surface
 *    take many small steps and end as MARCH_OUT_OF_STEPS rather than loop for ever;
 *  - max_distance 100: rays that leave it see the environment, and no surface lies there;
 *  - over_relaxation 1 (plain): safe for any bound; 1.2..1.6 saves steps on grazing rays, at the
 *    price of a step back when a step overshoots (see march());
 *  - no surface box: the whole of space may hold surfaces. */
SS_FN MarchSettings march_settings_default(float lipschitz) {
    MarchSettings s;
    s.epsilon_relative = 1e-4f;
    s.epsilon_min = 1e-5f;
    s.max_steps = 256;
    s.max_distance = 100.0f;
    s.surface_at_max_distance = 0;
    s.over_relaxation = 1.0f;
    s.lipschitz = lipschitz;
    /* without a loop, as render_march_settings (kernels/render_settings.h) */
    s.surface_lo[0] = s.surface_lo[1] = s.surface_lo[2] = -INFINITY;
    s.surface_hi[0] = s.surface_hi[1] = s.surface_hi[2] = INFINITY;
    return s;
}

/* The hit threshold at distance t along the ray (for one ray or, in a packet kernel, each lane): max(epsilon_min, epsilon_relative t), the scale of
 * the error in a hit point (callers offset secondary rays by a multiple of it). */
SS_FN SDF_FLOAT march_epsilon(MarchSettings s, SDF_FLOAT t) { return fmax(s.epsilon_relative * t, s.epsilon_min); }

#endif
