/* Sphere tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of
 * implicit surfaces"), with the over-relaxation of Keinert et al. 2014, "Enhanced Sphere Tracing", of
 * SDF_LANES rays at once (single_source/vocabulary.h): one ray on the host and in a scalar kernel
 * (march() in sdf/march.h is this for one lane), a packet of eight in the packet kernels
 * (kernels/march_packets.cl), where the march runs on the CPU's vector lanes. The rays of a packet
 * march together until every one has hit, left its max_distance or used max_steps; a lane that is
 * done keeps its result while the others go on. Each lane computes what the one-lane build computes,
 * the same operations in the same order, so both give the same t, status and steps to the bit.
 *
 * Needs the scene's field declared before it is included: scene_distance(float3) for one lane
 * (the generated scene source in a kernel; on the host see sdf/sdf.hpp), scene_distance_xyz with
 * SDF_FLOAT components and the mask of the lanes whose distance counts for a packet (the generated
 * source's packet form; a lane that is done gets a distance that may be too large, never used). */
#ifndef SDF_MARCH_LANES_H
#define SDF_MARCH_LANES_H

#include "single_source/vocabulary.h"
#include "sdf/march_settings.h"

#if defined(SDF_LANES)
/* the lanes still running: the box tests of the packet field heed only them */
#define MARCH_LANES_DISTANCE(x, y, z, running, evaluations) scene_distance_xyz(x, y, z, running)
#elif defined(SCENE_COUNT_EVALUATIONS)
/* a measurement build (`dtoadq bench breakdown`): the distance functions evaluated are counted */
#define MARCH_LANES_DISTANCE(x, y, z, running, evaluations) scene_distance_counted(make_float3(x, y, z), evaluations)
#else
#define MARCH_LANES_DISTANCE(x, y, z, running, evaluations) scene_distance(make_float3(x, y, z))
#endif

typedef struct MarchLanes {
    SDF_FLOAT t;      /* hit: the distance along the ray; otherwise where the march stopped */
    SDF_MASK status;  /* MARCH_HIT, MARCH_MISS or MARCH_OUT_OF_STEPS */
    SDF_MASK steps;   /* distance evaluations made for this lane */
} MarchLanes;

/* Marches each lane from o + t_start v (v unit) to the first surface, where
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
 * plain step -- and goes on with omega = 1. A failed step is not tested for a hit.
 *
 * A lane's max_distance replaces s.max_distance (a shadow ray's ends at its light); `evaluations`
 * counts in a measurement build only. */
SS_FN MarchLanes march_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, SDF_FLOAT t_start,
                             SDF_FLOAT max_distance, MarchSettings s, uint* evaluations) {
    (void)evaluations;
    MarchLanes m;
    m.t = t_start;
    m.steps = (SDF_MASK)0;
    SDF_MASK running = !(t_start > max_distance);
    m.status = select((SDF_MASK)MARCH_MISS, (SDF_MASK)MARCH_OUT_OF_STEPS, running);
    float inv_lipschitz = 1.0f / s.lipschitz;
    SDF_FLOAT omega = s.over_relaxation;
    SDF_FLOAT side = 1.0f; /* sign of the field at the start */
    SDF_FLOAT t_prev = t_start;
    SDF_FLOAT r_prev = 0.0f;
    SDF_FLOAT step = 0.0f;
    for (int i = 0; i < s.max_steps && SDF_ANY(running); ++i) {
        SDF_FLOAT d = MARCH_LANES_DISTANCE(ox + vx * m.t, oy + vy * m.t, oz + vz * m.t, running, evaluations) * inv_lipschitz;
        m.steps = select(m.steps, m.steps + (SDF_MASK)1, running);
        if (i == 0) side = select((SDF_FLOAT)1.0f, (SDF_FLOAT)-1.0f, d < 0.0f);
        SDF_FLOAT r = side * d; /* > 0 on the starting side */
        /* the over-relaxed step failed: back to the plain step, omega 1 from now on, no hit test */
        SDF_MASK failed = running && omega > 1.0f && (r < 0.0f || step > r_prev + r);
        m.t = select(m.t, t_prev + r_prev, failed);
        step = select(step, r_prev, failed);
        omega = select(omega, (SDF_FLOAT)1.0f, failed);
        SDF_MASK tested = running && !failed;
        SDF_MASK hit = tested && fabs(r) < march_epsilon(s, m.t);
        m.status = select(m.status, (SDF_MASK)MARCH_HIT, hit);
        running = running && !hit;
        /* r < 0 only with omega = 1: a crossing through rounding or a field that is not a bound;
         * stepping by r goes back towards the surface. */
        SDF_MASK advance = tested && !hit;
        t_prev = select(t_prev, m.t, advance);
        r_prev = select(r_prev, r, advance);
        step = select(step, omega * r, advance);
        m.t = select(m.t, m.t + step, advance);
        SDF_MASK miss = advance && m.t > max_distance;
        m.status = select(m.status, (SDF_MASK)MARCH_MISS, miss);
        running = running && !miss;
    }
    return m;
}

#endif
