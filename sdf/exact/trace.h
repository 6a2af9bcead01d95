/* One ray of a scene whose plain primitives are intersected exactly: the nearer of the exact hit
 * and a march cut there (sdf/exact/with_march.h). Needs, besides what sdf/march.h needs,
 * scene_exact_hit(o, v, t_max) and scene_march_objects() declared before it is included (the
 * generated scene source; on the host scene/field_for_kernel_headers.hpp). */
#ifndef SDF_EXACT_TRACE_H
#define SDF_EXACT_TRACE_H

#include "single_source/vocabulary.h"
#include "sdf/exact/with_march.h"
#include "sdf/march.h"

SS_FN MarchResult march_scene_ray(float3 origin, float3 direction, MarchSettings s) {
    const float max_distance = s.max_distance;
    const float t_exact = scene_exact_hit(origin, direction, max_distance);
    s.max_distance = exact_march_limit(max_distance, t_exact, scene_march_objects());
    s.surface_at_max_distance = t_exact <= max_distance;
    MarchResult r = march(origin, direction, 0.0f, s);
    exact_or_march(t_exact, max_distance, &r.t, &r.status);
    return r;
}

#endif
