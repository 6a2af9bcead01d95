/* A ray's nearest hit in a scene whose plain primitives are intersected exactly and whose other
 * objects are sphere-traced (scene/generated_source.cpp says which is which): the nearer of the
 * nearest exact hit and the march. The march is limited to the exact hit, so it never marches past
 * a wall the ray will hit; it finds a surface before that or ends as a miss, and the exact hit is
 * taken. A march that runs out of steps before the exact hit also takes it: the ray found nothing
 * nearer that it could resolve, and the wall is certainly there. One rule for every ray (camera,
 * continuation, shadow and connection rays, one at a time or in packets). */
#ifndef SDF_EXACT_WITH_MARCH_H
#define SDF_EXACT_WITH_MARCH_H

#include "single_source/vocabulary.h"
#include "sdf/march_settings.h"

/* The march's max distance: the ray's own, cut at the nearest exact hit; -1 (a march that is done
 * before its first step, a miss) when the field holds no object to march. */
SS_FN float exact_march_limit(float max_distance, float t_exact, int marched_objects) {
    return marched_objects > 0 ? fmin(max_distance, t_exact) : -1.0f;
}

/* The march's result (t, status) made the ray's: the exact hit unless the march hit first. */
SS_FN void exact_or_march(float t_exact, float max_distance, float* t, int* status) {
    if (*status != MARCH_HIT && t_exact <= max_distance) {
        *t = t_exact;
        *status = MARCH_HIT;
    }
}

#ifdef SDF_LANES /* the lane forms: the rules above for eight rays at once */
SS_FN SDF_FLOAT exact_march_limit_lanes(SDF_FLOAT max_distance, SDF_FLOAT t_exact, int marched_objects) {
    return marched_objects > 0 ? fmin(max_distance, t_exact) : (SDF_FLOAT)-1.0f;
}

SS_FN void exact_or_march_lanes(SDF_FLOAT t_exact, SDF_FLOAT max_distance, SDF_FLOAT* t, SDF_MASK* status) {
    SDF_MASK exact = *status != (SDF_MASK)MARCH_HIT && t_exact <= max_distance;
    *t = select(*t, t_exact, exact);
    *status = select(*status, (SDF_MASK)MARCH_HIT, exact);
}
#endif

#endif
