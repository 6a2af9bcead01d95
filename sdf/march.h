/* Sphere tracing of the scene (Hart 1996, "Sphere tracing: a geometric method for the antialiased
 * ray tracing of implicit surfaces"), with the over-relaxation of Keinert et al. 2014, "Enhanced
 * Sphere Tracing".
 * Needs `float scene_distance(float3 p)` declared before this header is included: the generated
 * scene source defines it in a kernel; on the host see sdf/sdf.hpp. */
#ifndef SDF_MARCH_H
#define SDF_MARCH_H

#include "single_source/vocabulary.h"

#include "sdf/march_settings.h"

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
