/* Plain sphere tracing of SDF_LANES rays at once (single_source/vocabulary.h): one ray on the host
 * and in a scalar kernel, a packet of eight in kernels/camera_march.cl, where the march runs on the
 * CPU's vector lanes. The rays march together until every one has hit, left max_distance, or used
 * max_steps; a lane that is done keeps its result while the others go on (its further evaluations
 * are the packet's cost).
 *
 * Each lane computes exactly what march() (sdf/march.h) computes with over_relaxation 1 from
 * t_start = 0: the same evaluations in the same order, so the host's one-lane build and a device's
 * eight-lane build give the same t, status and steps to the bit. Over-relaxation's step back is left
 * out: its gain is on grazing rays, the few that a packet's other lanes wait for anyway.
 *
 * Needs scene_distance_xyz (SDF_FLOAT components) declared before it is included: the generated
 * scene source in a kernel; on the host see sdf/sdf.hpp. */
#ifndef SDF_MARCH_LANES_H
#define SDF_MARCH_LANES_H

#include "single_source/vocabulary.h"
#include "sdf/march_settings.h"

#if defined(SCENE_COUNT_EVALUATIONS) && !defined(SDF_LANES)
/* a measurement build (`dtoadq bench breakdown`): the distance functions evaluated are counted */
#define MARCH_LANES_DISTANCE(x, y, z, evaluations) scene_distance_counted(make_float3(x, y, z), evaluations)
#else
#define MARCH_LANES_DISTANCE(x, y, z, evaluations) scene_distance_xyz(x, y, z)
#endif

typedef struct MarchLanes {
    SDF_FLOAT t;      /* hit: the distance along the ray; otherwise where the march stopped */
    SDF_MASK status;  /* MARCH_HIT, MARCH_MISS or MARCH_OUT_OF_STEPS */
    SDF_MASK steps;   /* distance evaluations made for this lane */
} MarchLanes;

/* origin o, unit direction v, per lane. `evaluations` counts in a measurement build only. */
SS_FN MarchLanes march_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, MarchSettings s,
                             uint* evaluations) {
    (void)evaluations;
    MarchLanes m;
    m.t = 0.0f;
    m.status = (SDF_MASK)MARCH_OUT_OF_STEPS;
    m.steps = (SDF_MASK)0;
    if (0.0f > s.max_distance) { /* as march() with t_start = 0 */
        m.status = (SDF_MASK)MARCH_MISS;
        return m;
    }
    float inv_lipschitz = 1.0f / s.lipschitz;
    SDF_FLOAT side = 1.0f; /* sign of the field at the start */
    SDF_MASK running = m.t == m.t;
    for (int i = 0; i < s.max_steps && SDF_ANY(running); ++i) {
        SDF_FLOAT d = MARCH_LANES_DISTANCE(ox + vx * m.t, oy + vy * m.t, oz + vz * m.t, evaluations) * inv_lipschitz;
        m.steps = select(m.steps, m.steps + (SDF_MASK)1, running);
        if (i == 0) side = select((SDF_FLOAT)1.0f, (SDF_FLOAT)-1.0f, d < 0.0f);
        SDF_FLOAT r = side * d; /* > 0 on the starting side */
        SDF_MASK hit = running && fabs(r) < march_epsilon(s, m.t);
        m.status = select(m.status, (SDF_MASK)MARCH_HIT, hit);
        running = running && !hit;
        m.t = select(m.t, m.t + r, running);
        SDF_MASK miss = running && m.t > s.max_distance;
        m.status = select(m.status, (SDF_MASK)MARCH_MISS, miss);
        running = running && !miss;
    }
    return m;
}

#endif
