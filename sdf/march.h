/* Sphere tracing of the scene (Hart 1996, "Sphere tracing: a geometric method for the antialiased
 * ray tracing of implicit surfaces"), with the over-relaxation of Keinert et al. 2014, "Enhanced
 * Sphere Tracing".
 * Needs `float scene_distance(float3 p)` declared before this header is included: the generated
 * scene source defines it in a kernel; on the host see sdf/sdf.hpp. */
#ifndef SDF_MARCH_H
#define SDF_MARCH_H

#include "single_source/vocabulary.h"

#define MARCH_HIT 0
#define MARCH_MISS 1         /* the ray left max_distance */
#define MARCH_OUT_OF_STEPS 2 /* max_steps distance evaluations without a hit or a miss */

typedef struct MarchSettings {
    float epsilon_relative; /* hit when |d| / lipschitz < max(epsilon_min, epsilon_relative * t) */
    float epsilon_min;
    int max_steps;          /* distance evaluations */
    float max_distance;     /* along the ray, from the origin */
    float over_relaxation;  /* omega: 1 = plain sphere tracing; 1.2..1.6 Keinert et al. 2014 */
    float lipschitz;        /* distances are divided by this (the scene's bound, >= 1) */
} MarchSettings;

typedef struct MarchResult {
    float t;     /* hit: the distance along the ray; otherwise where the march stopped */
    int status;  /* MARCH_HIT, MARCH_MISS or MARCH_OUT_OF_STEPS */
    int steps;   /* distance evaluations made */
#ifdef SCENE_COUNT_EVALUATIONS
    uint evaluations; /* a measurement build: the objects' distance functions evaluated (scene/compile.cpp) */
#endif
} MarchResult;

#ifdef SCENE_COUNT_EVALUATIONS
#define MARCH_SCENE_DISTANCE(p, result) scene_distance_counted(p, &(result).evaluations)
#else
#define MARCH_SCENE_DISTANCE(p, result) scene_distance(p)
#endif

/* Defaults for scenes of a few units to a few tens of units across:
 *  - epsilon_relative 1e-4: the hit threshold grows with t like a pixel's footprint (1e-4 rad is
 *    about a pixel of a 60-degree 1000-pixel image), far above float rounding (~1e-7 t);
 *  - epsilon_min 1e-5: the threshold near the origin, where epsilon_relative * t vanishes;
 *  - max_steps 256: plain tracing reaches most surfaces in tens of steps; rays grazing a surface
 *    take many small steps and end as MARCH_OUT_OF_STEPS rather than loop for ever;
 *  - max_distance 100: rays that leave it see the environment;
 *  - over_relaxation 1 (plain): safe for any bound; 1.2..1.6 saves steps on grazing rays, at the
 *    price of a step back when a step overshoots (see march()). */
SS_FN MarchSettings march_settings_default(float lipschitz) {
    MarchSettings s;
    s.epsilon_relative = 1e-4f;
    s.epsilon_min = 1e-5f;
    s.max_steps = 256;
    s.max_distance = 100.0f;
    s.over_relaxation = 1.0f;
    s.lipschitz = lipschitz;
    return s;
}

/* The hit threshold at distance t along the ray: max(epsilon_min, epsilon_relative t), the scale of
 * the error in a hit point (callers offset secondary rays by a multiple of it). */
SS_FN float march_epsilon(MarchSettings s, float t) { return fmax(s.epsilon_min, s.epsilon_relative * t); }

/* Marches from origin + t_start direction (direction unit) to the first surface, where
 * |scene_distance| / lipschitz < max(epsilon_min, epsilon_relative t).
 *
 * The radius r = |scene_distance(p)| / lipschitz is a sphere around p free of surface, so a step of
 * r is safe (Hart 1996). The march works on |d|, so it finds the surface from inside a solid too
 * (refraction; the caller offsets the origin past epsilon, or it hits at t_start). The sign of the
 * field where the march started is kept: a later sign change means the ray crossed a surface.
 *
 * Over-relaxation (omega > 1, Keinert et al. 2014, section 3.1): step omega r instead of r. The step
 * from t_prev to t is still safe when the spheres at both ends overlap, omega r_prev <= r_prev + r;
 * when they do not (or the sign changed: the ray crossed a surface, the spheres touching just at
 * that surface), a surface may lie in the gap, so the march steps back to t_prev + r_prev -- the
 * plain step -- and goes on with omega = 1. A failed step is not tested for a hit. */
SS_FN MarchResult march(float3 origin, float3 direction, float t_start, MarchSettings s) {
    MarchResult result;
    result.t = t_start;
    result.status = MARCH_OUT_OF_STEPS;
    result.steps = 0;
#ifdef SCENE_COUNT_EVALUATIONS
    result.evaluations = 0u;
#endif
    if (t_start > s.max_distance) {
        result.status = MARCH_MISS;
        return result;
    }
    float inv_lipschitz = 1.0f / s.lipschitz;
    float omega = s.over_relaxation;
    float side = 1.0f; /* sign of the field at the start */
    float t = t_start;
    float t_prev = t_start;
    float r_prev = 0.0f;
    float step = 0.0f;
    for (int i = 0; i < s.max_steps; ++i) {
        float d = MARCH_SCENE_DISTANCE(origin + direction * t, result) * inv_lipschitz;
        result.steps = i + 1;
        if (i == 0) side = d < 0.0f ? -1.0f : 1.0f;
        float r = side * d; /* > 0 on the starting side */
        if (omega > 1.0f && (r < 0.0f || step > r_prev + r)) {
            t = t_prev + r_prev;
            step = r_prev;
            omega = 1.0f;
            continue;
        }
        if (fabs(r) < march_epsilon(s, t)) {
            result.t = t;
            result.status = MARCH_HIT;
            return result;
        }
        /* r < 0 only with omega = 1: a crossing through rounding or a field that is not a bound;
         * stepping by r goes back towards the surface. */
        t_prev = t;
        r_prev = r;
        step = omega * r;
        t += step;
        if (t > s.max_distance) {
            result.t = t;
            result.status = MARCH_MISS;
            return result;
        }
    }
    result.t = t;
    return result;
}

#endif
