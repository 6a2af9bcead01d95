/* Sphere tracing of the scene, one ray at a time (the algorithm: sdf/march_lanes.h).
 * Needs `float scene_march_distance(float3 p)` declared before this header is included: the generated
 * scene source defines it in a kernel; on the host see sdf/sdf.hpp. */
#ifndef SDF_MARCH_H
#define SDF_MARCH_H

#include "single_source/vocabulary.h"

#include "sdf/march_lanes.h"
#include "sdf/march_settings.h"

typedef struct MarchResult {
    float t;     /* hit: the distance along the ray; otherwise where the march stopped */
    int status;  /* MARCH_HIT, MARCH_MISS or MARCH_OUT_OF_STEPS */
    int steps;   /* distance evaluations made */
#ifdef SCENE_COUNT_EVALUATIONS
    uint evaluations; /* a measurement build: the objects' distance functions evaluated (scene/generated_source.cpp) */
#endif
} MarchResult;

/* One ray: march_lanes (sdf/march_lanes.h, which says how) for a single lane. */
SS_FN MarchResult march(float3 origin, float3 direction, float t_start, MarchSettings s) {
    uint evaluations = 0u;
    MarchLanes m = march_lanes(origin.x, origin.y, origin.z, direction.x, direction.y, direction.z, t_start, s.max_distance, s, &evaluations);
    MarchResult result;
    result.t = m.t;
    result.status = m.status;
    result.steps = m.steps;
#ifdef SCENE_COUNT_EVALUATIONS
    result.evaluations = evaluations;
#endif
    return result;
}

#endif
