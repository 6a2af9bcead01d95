/* What every integrator's paths share: marching a ray with its counters, the surface a ray hit
 * (point, material slot, shading frame, the error scale of the point), offsetting rays off a
 * surface, and shadow rays. Needs the scene (scene_distance, scene_distance_material,
 * scene_analytic_normal, scene_surface, scene_exact_hit, scene_march_objects) declared before it is included, like sdf/march.h: the generated scene
 * source in a kernel, the host interpreter in render/host_renderer.cpp. */
#ifndef KERNELS_PATH_H
#define KERNELS_PATH_H

#include "single_source/vocabulary.h"
#include "brdf/frame.h"
#include "kernels/render_settings.h"
#include "sdf/exact/trace.h"
#include "sdf/march.h"
#include "sdf/normals.h"

/* Per-pixel counters the host reads for its statistics. */
typedef struct PathCounters {
    uint rays;      /* marches: camera, continuation and shadow rays */
    uint lost_rays; /* marches that ran out of steps (treated as escaping, or as shadowed) */
} PathCounters;

SS_FN PathCounters path_counters_zero(void) {
    PathCounters counters;
    counters.rays = 0u;
    counters.lost_rays = 0u;
    return counters;
}

/* A march in the per-pixel counters. */
SS_FN void count_march(MarchResult r, PathCounters* counters) {
#ifdef SCENE_COUNT_EVALUATIONS
    /* a measurement build (`dtoadq bench breakdown`): the counters hold march steps and distance
     * evaluations instead; the paths are the same as the default build's */
    counters->rays += (uint)r.steps;
    counters->lost_rays += r.evaluations;
#else
    counters->rays += 1u;
    if (r.status == MARCH_OUT_OF_STEPS) counters->lost_rays += 1u;
#endif
}

/* A ray's nearest hit: the exact hits of the plain primitives and the march of the rest
 * (march_scene_ray, sdf/exact/trace.h). */
SS_FN MarchResult trace_ray(float3 origin, float3 direction, MarchSettings march_settings, PathCounters* counters) {
    MarchResult r = march_scene_ray(origin, direction, march_settings);
    count_march(r, counters);
    return r;
}

/* Starts a ray off a surface on the side it leaves into (side: the sign of the new direction's
 * cosine with n): twice the hit threshold clears the surface's own |d| < epsilon band, so the march
 * does not stop where it starts. */
SS_FN float3 offset_origin(float3 p, float3 n, float epsilon, float side) {
    return p + n * (side > 0.0f ? 2.0f * epsilon : -2.0f * epsilon);
}

/* A normal estimated at an edge, or at a grazing hit, can face away from the side the ray came
 * from (finite differences straddle the edge; the hit lies within epsilon of the surface). The
 * BSDF would then see the ray arrive from below and absorb it. Bend such a normal towards that side
 * just far enough that it faces it; `toward` is the unit vector back along the ray. */
#define MIN_FACING_COSINE 1e-3f
SS_FN float3 facing_normal(float3 n, float3 toward) {
    float facing = dot(n, toward);
    if (facing >= MIN_FACING_COSINE) return n;
    return normalize(n + toward * (MIN_FACING_COSINE - facing));
}

/* Anisotropy follows the lines of latitude about +y: brushed metal on a shader ball is brushed round it. */
SS_FN ShadingFrame shading_frame(float3 n) { return frame_from_normal_tangent(n, make_float3(n.z, 0.0f, -n.x)); }

/* The material slot and the outward normal at a hit point: an exactly intersected object's
 * analytic normal whatever the normal method (its hit is exact, so finite differences would only
 * add their error), else the method's. */
SS_FN float3 surface_normal(const RenderKernelSettings* settings, float3 p, int* slot) {
    float3 n;
    if (scene_surface(p, slot, &n)) return n;
    return scene_normal(p, settings->normal_step, settings->normal_method);
}

/* The surface a ray hit, as a path sees it. */
typedef struct SurfaceHit {
    float3 p;           /* the hit point */
    int slot;           /* its material slot */
    ShadingFrame frame; /* outward normal (the BSDF tells the sides apart), anisotropy tangent */
    float3 wo;          /* back along the ray, in the frame */
    float epsilon;      /* the march's hit threshold there: the scale of the error in p */
} SurfaceHit;

/* `inside`: the ray travels in a solid (only transmission gets a ray there), so the side it came
 * from is the inner one; the frame's normal stays outward and that side must face it. */
SS_FN SurfaceHit surface_hit(const RenderKernelSettings* settings, MarchSettings march_settings, float3 origin, float3 direction, float t, bool inside) {
    SurfaceHit h;
    h.p = origin + direction * t;
    float3 outward = surface_normal(settings, h.p, &h.slot);
    h.frame = shading_frame(inside ? -facing_normal(-outward, -direction) : facing_normal(outward, -direction));
    h.wo = frame_to_local(h.frame, -direction);
    h.epsilon = march_epsilon(march_settings, t);
    return h;
}

/* The hit seen as a two-sided surface: the frame turned over, if need be, so that its normal faces
 * the side the ray came from. For surfaces that scatter on both sides whatever solid they bound
 * (emissive spheres seen from inside). */
SS_FN SurfaceHit facing_side(SurfaceHit h) {
    if (h.wo.z >= 0.0f) return h;
    h.frame.n = -h.frame.n;
    h.frame.b = -h.frame.b; /* keeps the frame right-handed */
    h.wo = make_float3(h.wo.x, -h.wo.y, -h.wo.z);
    return h;
}

/* A shadow ray: from `origin` along unit `direction` to what lies `distance` away, a point light or
 * the environment (target_slot < 0: nothing may be hit before `distance`), or a point on an
 * emissive sphere (target_slot: its material slot; the ray may end on that sphere, which the march
 * reports as a hit short of `distance` when it grazes it). `contribution` is what it brings when it
 * gets there. Vectors are float[3]: the struct is stored in kernels' buffers. */
typedef struct ShadowRay {
    float origin[3], direction[3];
    float distance;
    int target_slot;
    float contribution[3];
    int pending; /* while the ray is to be marched: SHADOW_COUNTS_IF_REACHED, or SHADOW_COUNTS_IF_BLOCKED */
} ShadowRay;

/* A shadow ray's contribution counts where it reaches its light (next-event estimation), or where
 * it is blocked: at a shadow catcher, the light the other objects take away (kernels/path_tracer.h). */
#define SHADOW_COUNTS_IF_REACHED 1
#define SHADOW_COUNTS_IF_BLOCKED 2

/* Whether the shadow ray got there, given its march (trace_shadow_ray, or a packet kernel's with
 * the same settings). A ray that runs out of steps counts as shadowed. */
SS_FN bool segment_reached(float3 origin, float3 direction, int target_slot, MarchResult r) {
    if (r.status == MARCH_MISS) return true;
    if (r.status != MARCH_HIT || target_slot < 0) return false;
    int slot;
    scene_distance_material(origin + direction * r.t, &slot);
    return slot == target_slot;
}

SS_FN bool shadow_reached(const ShadowRay* shadow, MarchResult r) {
    return segment_reached(float3_from_array(shadow->origin), float3_from_array(shadow->direction), shadow->target_slot, r);
}

/* A shadow ray's march: it ends at the ray's distance. */
SS_FN float shadow_max_distance(MarchSettings march_settings, float distance) { return fmin(march_settings.max_distance, distance); }

SS_FN MarchResult trace_shadow_ray(const ShadowRay* shadow, MarchSettings march_settings, PathCounters* counters) {
    march_settings.max_distance = shadow_max_distance(march_settings, shadow->distance);
    return trace_ray(float3_from_array(shadow->origin), float3_from_array(shadow->direction), march_settings, counters);
}

/* Whether a shadow ray (ShadowRay's fields) reaches what it aims at. */
SS_FN bool segment_unoccluded(float3 origin, float3 direction, float distance, int target_slot, MarchSettings march_settings,
                              PathCounters* counters) {
    march_settings.max_distance = shadow_max_distance(march_settings, distance);
    return segment_reached(origin, direction, target_slot, trace_ray(origin, direction, march_settings, counters));
}

#endif
