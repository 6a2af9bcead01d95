/* Sphere tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of
 * implicit surfaces"), with the over-relaxation of Keinert et al. 2014, "Enhanced Sphere Tracing", of
 * SDF_LANES rays at once (single_source/vocabulary.h): one ray on the host and in a scalar kernel
 * (march() in sdf/march.h is this for one lane), a packet of eight in the packet kernels
 * (kernels/march_packets.cl), where the march runs on the CPU's vector lanes. The lanes step
 * together; a lane that has hit, left its max_distance or used max_steps stops, and a packet kernel
 * may start the next ray in it while the others go on. Each lane computes what the one-lane build
 * computes, the same operations in the same order, so both give the same t, status and steps to the
 * bit.
 *
 * Needs the scene's field declared before it is included: scene_march_distance(float3) for one lane,
 * the objects that are not intersected exactly (sdf/exact/with_march.h; the generated scene source
 * in a kernel; on the host see sdf/sdf.hpp), scene_distance_xyz with
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
#define MARCH_LANES_DISTANCE(x, y, z, running, evaluations) scene_march_distance_counted(make_float3(x, y, z), evaluations)
#else
#define MARCH_LANES_DISTANCE(x, y, z, running, evaluations) scene_march_distance(make_float3(x, y, z))
#endif

typedef struct MarchLanes {
    SDF_FLOAT t;      /* hit: the distance along the ray; otherwise where the march stopped */
    SDF_MASK status;  /* MARCH_HIT, MARCH_MISS or MARCH_OUT_OF_STEPS */
    SDF_MASK steps;   /* distance evaluations made for this lane */
} MarchLanes;

/* One axis's slab [lo - grow, hi + grow] for march_surface_exit: narrows [*enter, *exit]. */
SS_FN void march_surface_slab(float lo, float hi, SDF_FLOAT grow, SDF_FLOAT o, SDF_FLOAT v, SDF_FLOAT* enter, SDF_FLOAT* exit) {
    SDF_FLOAT t0 = (lo - grow - o) / v, t1 = (hi + grow - o) / v;
    *enter = fmax(*enter, fmin(t0, t1));
    *exit = fmin(*exit, fmax(t0, t1));
}

/* Where a ray o + t v leaves the surface box of s for good, grown by the distance within which a
 * point counts as a hit (below), by the slabs of Kay and Kajiya 1986: the least of the axes' far
 * ends. -INFINITY when the ray misses the box, so that it starts past it; INFINITY when the box is
 * unbounded where the ray goes. A component v = 0 divides to +-INFINITY, which the slabs take as
 * they should (0 / 0, a ray along a face of the grown box, is a NaN that fmin and fmax drop).
 *
 * Why the march may stop there: the compiler's box B holds the solid with f(p) >= dist(p, B)
 * outside it (scene/lipschitz.hpp), and a point is a hit when f / lipschitz < epsilon(t) <=
 * epsilon(max_distance), so no point farther than lipschitz epsilon(max_distance) from B is one,
 * and a ray that has left a box never enters it again.
 *
 * The three slabs are three calls with constant indices, not a loop over arrays: PoCL kept such a
 * loop, and the copy of the settings it indexes, in memory, where every restart of a packet lane
 * paid a store-forwarding stall for it (a tenth of the packet march's time on the sphere). */
SS_FN SDF_FLOAT march_surface_exit(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, MarchSettings s) {
    SDF_FLOAT grow = s.lipschitz * march_epsilon(s, (SDF_FLOAT)s.max_distance);
    SDF_FLOAT enter = -INFINITY, exit = INFINITY;
    march_surface_slab(s.surface_lo[0], s.surface_hi[0], grow, ox, vx, &enter, &exit);
    march_surface_slab(s.surface_lo[1], s.surface_hi[1], grow, oy, vy, &enter, &exit);
    march_surface_slab(s.surface_lo[2], s.surface_hi[2], grow, oz, vz, &enter, &exit);
    return select(exit, (SDF_FLOAT)-INFINITY, enter > exit);
}

/* A march between two steps, per lane: its result so far, whether it still runs, and what the next
 * step needs (the over-relaxation state below). Each lane's march depends on its own fields only,
 * so a packet kernel may start a new ray in a lane whose march is done (march_lanes_restart) while
 * the others go on. */
typedef struct MarchLanesState {
    MarchLanes m;
    SDF_MASK running;
    SDF_FLOAT side;   /* sign of the field at the start */
    SDF_FLOAT t_prev; /* where the last step that was not undone started */
    SDF_FLOAT r_prev; /* its safe radius */
    SDF_FLOAT step;   /* the length of that step */
    SDF_FLOAT omega;  /* the over-relaxation: s.over_relaxation, 1 after a failed step */
    SDF_FLOAT exit;   /* march_surface_exit of the ray */
    SDF_MASK surface_at_end; /* a surface lies at the lane's max distance (MarchSettings) */
} MarchLanesState;

/* Each lane's march of o + t v from t_start, before its first step: running unless t_start is past
 * its max_distance or the ray's exit from the surface box (a miss with no step) or max_steps is 0
 * (out of steps). surface_at_end: the lanes whose max distance is a surface's (MarchSettings'
 * surface_at_max_distance, lane by lane). */
SS_FN MarchLanesState march_lanes_start(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, SDF_FLOAT t_start,
                                        SDF_FLOAT max_distance, SDF_MASK surface_at_end, MarchSettings s) {
    MarchLanesState st;
    st.m.t = t_start;
    st.m.steps = (SDF_MASK)0;
    st.exit = march_surface_exit(ox, oy, oz, vx, vy, vz, s);
    st.running = !(t_start > max_distance) && !(t_start > st.exit);
    st.m.status = select((SDF_MASK)MARCH_MISS, (SDF_MASK)MARCH_OUT_OF_STEPS, st.running);
    st.running = st.running && (SDF_MASK)0 < (SDF_MASK)s.max_steps;
    st.side = 1.0f;
    st.t_prev = t_start;
    st.r_prev = 0.0f;
    st.step = 0.0f;
    st.omega = s.over_relaxation;
    st.surface_at_end = surface_at_end;
    return st;
}

/* The lanes of `lanes` begin again at t_start (march_lanes_start); the others keep their march. */
SS_FN MarchLanesState march_lanes_restart(MarchLanesState st, SDF_MASK lanes, SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy,
                                          SDF_FLOAT vz, SDF_FLOAT t_start, SDF_FLOAT max_distance, SDF_MASK surface_at_end, MarchSettings s) {
    MarchLanesState fresh = march_lanes_start(ox, oy, oz, vx, vy, vz, t_start, max_distance, surface_at_end, s);
    st.m.t = select(st.m.t, fresh.m.t, lanes);
    st.m.status = select(st.m.status, fresh.m.status, lanes);
    st.m.steps = select(st.m.steps, fresh.m.steps, lanes);
    st.running = select(st.running, fresh.running, lanes);
    st.side = select(st.side, fresh.side, lanes);
    st.t_prev = select(st.t_prev, fresh.t_prev, lanes);
    st.r_prev = select(st.r_prev, fresh.r_prev, lanes);
    st.step = select(st.step, fresh.step, lanes);
    st.omega = select(st.omega, fresh.omega, lanes);
    st.exit = select(st.exit, fresh.exit, lanes);
    st.surface_at_end = select(st.surface_at_end, fresh.surface_at_end, lanes);
    return st;
}

/* One step of every running lane along o + t v (v unit), towards the first surface, where
 * |scene_distance| / lipschitz < max(epsilon_min, epsilon_relative t).
 *
 * The radius r = |scene_distance(p)| / lipschitz is a sphere around p free of surface, so a step of
 * r is safe (Hart 1996). The march works on |d|, so it finds the surface from inside a solid too
 * (refraction; the caller offsets the origin past epsilon, or it hits at t_start). The sign of the
 * field at a lane's first step is kept: a later sign change means the ray crossed a surface.
 *
 * Over-relaxation (omega > 1, Keinert et al. 2014, section 3.1): step omega r instead of r. The step
 * from t_prev to t is still safe when the spheres at both ends overlap, omega r_prev <= r_prev + r;
 * when they do not (or the sign changed: the ray crossed a surface, the spheres touching just at
 * that surface), a surface may lie in the gap, so the march steps back to t_prev + r_prev -- the
 * plain step -- and goes on with omega = 1. A failed step is not tested for a hit.
 *
 * A lane stops when it hits, passes its max_distance (a miss) or has made s.max_steps steps (out of
 * steps); `evaluations` counts in a measurement build only. It also ends as a miss once its ray
 * has left the surface box (march_surface_exit), with the safe sphere of its last point reaching
 * past the exit, so that an over-relaxed step that overshot is still checked first. Until then the
 * steps are those of a march without the box: the box changes where a miss stops, not what is hit. */
SS_FN void march_lanes_advance(MarchLanesState* st, SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz,
                               SDF_FLOAT max_distance, MarchSettings s, uint* evaluations) {
    (void)evaluations;
    SDF_MASK running = st->running;
    SDF_FLOAT t = st->m.t;
    SDF_FLOAT d = MARCH_LANES_DISTANCE(ox + vx * t, oy + vy * t, oz + vz * t, running, evaluations) * (1.0f / s.lipschitz);
    SDF_MASK first = running && st->m.steps == (SDF_MASK)0;
    st->m.steps = select(st->m.steps, st->m.steps + (SDF_MASK)1, running);
    st->side = select(st->side, select((SDF_FLOAT)1.0f, (SDF_FLOAT)-1.0f, d < 0.0f), first);
    SDF_FLOAT r = st->side * d; /* > 0 on the starting side */
    /* the over-relaxed step failed: back to the plain step, omega 1 from now on, no hit test */
    SDF_MASK failed = running && st->omega > 1.0f && (r < 0.0f || st->step > st->r_prev + r);
    t = select(t, st->t_prev + st->r_prev, failed);
    st->step = select(st->step, st->r_prev, failed);
    st->omega = select(st->omega, (SDF_FLOAT)1.0f, failed);
    SDF_MASK tested = running && !failed;
    SDF_MASK hit = tested && fabs(r) < march_epsilon(s, t);
    st->m.status = select(st->m.status, (SDF_MASK)MARCH_HIT, hit);
    running = running && !hit;
    /* r < 0 only with omega = 1: a crossing through rounding or a field that is not a bound;
     * stepping by r goes back towards the surface. */
    SDF_MASK advance = tested && !hit;
    st->t_prev = select(st->t_prev, t, advance);
    st->r_prev = select(st->r_prev, r, advance);
    st->step = select(st->step, st->omega * r, advance);
    t = select(t, t + st->step, advance);
    /* past the max distance: where a surface lies there, only once the verified safe sphere reaches
     * it (an over-relaxed step that leapt past it is checked first, as at the surface box's exit) */
    SDF_MASK past_end = select((SDF_MASK)(t > max_distance), (SDF_MASK)(st->t_prev + st->r_prev > max_distance), st->surface_at_end);
    SDF_MASK miss = advance && (past_end || st->t_prev + st->r_prev > st->exit);
    st->m.status = select(st->m.status, (SDF_MASK)MARCH_MISS, miss);
    running = running && !miss;
    st->m.t = t;
    st->running = running && st->m.steps < (SDF_MASK)s.max_steps;
}

/* Marches each lane from o + t_start v to its first surface (march_lanes_advance); a lane's
 * max_distance replaces s.max_distance (a shadow ray's ends at its light), and every lane takes
 * s.surface_at_max_distance. */
SS_FN MarchLanes march_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, SDF_FLOAT t_start,
                             SDF_FLOAT max_distance, MarchSettings s, uint* evaluations) {
    MarchLanesState st = march_lanes_start(ox, oy, oz, vx, vy, vz, t_start, max_distance, (SDF_MASK)(s.surface_at_max_distance != 0 ? -1 : 0), s);
    while (SDF_ANY(st.running)) march_lanes_advance(&st, ox, oy, oz, vx, vy, vz, max_distance, s, evaluations);
    return st.m;
}

#endif
