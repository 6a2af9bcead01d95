/* The image-based-lighting preview: a unidirectional path tracer of one compiled SDF scene under a
 * cubemap environment. Each launch adds `sample_count` samples to every pixel's running sum; the
 * host divides by the samples taken. Strategies for the environment (IBL_SAMPLING_*):
 *   BRDF: continue the path by sampling the BSDF and add the environment where it escapes;
 *   ENV:  next-event estimation only (sample the environment, trace a shadow ray), escaping BSDF
 *         samples count only after delta events, which the environment sampler cannot produce;
 *   MIS:  both, weighted by the power heuristic (Veach 1997), so each covers where the other is poor.
 * Emissive spheres are found by the path only (no next-event estimation here; the BDPT has it). */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

#include "brdf/bsdf.h"
#include "ibl/environment.h"
#include "kernels/material_layout.h"
#include "kernels/mis.h"
#include "kernels/camera.h"
#include "kernels/preview_settings.h"
#include "kernels/rng.h"
#include "sdf/march.h"
#include "sdf/normals.h"

/* The settings, with the march's gathered into sdf/march.h's struct. */
typedef struct PreviewSettings {
    PreviewKernelSettings k;
    MarchSettings march;
} PreviewSettings;

static PreviewSettings preview_settings(PreviewKernelSettings k) {
    PreviewSettings s;
    s.k = k;
    s.march = march_settings_default(k.lipschitz);
    s.march.max_steps = k.max_steps;
    s.march.max_distance = k.max_distance;
    s.march.over_relaxation = k.over_relaxation;
    return s;
}

/* Per-pixel counters the host reads for its statistics. */
typedef struct PathCounters {
    uint rays;       /* marches: camera, continuation and shadow rays */
    uint lost_rays;  /* marches that ran out of steps (treated as escaping, or as shadowed) */
} PathCounters;

typedef struct EnvironmentBuffers {
    GLOBAL_MEM const float4* texels;
    GLOBAL_MEM const float* marginal_cdf;
    GLOBAL_MEM const float* conditional_cdf;
} EnvironmentBuffers;

/* Starts a ray off a surface on the side it leaves into: twice the hit threshold clears the
 * surface's own |d| < epsilon band, so the march does not stop where it starts. */
static float3 offset_origin(float3 p, float3 n, float epsilon, float side) { return p + n * (side > 0.0f ? 2.0f * epsilon : -2.0f * epsilon); }

/* A normal estimated at an edge, or at a grazing hit, can face away from the side the ray came
 * from (finite differences straddle the edge; the hit lies within epsilon of the surface). The
 * BSDF would then see the ray arrive from below and absorb it. Bend such a normal towards that side
 * just far enough that it faces it; `toward` is the unit vector back along the ray. */
#define MIN_FACING_COSINE 1e-3f
static float3 facing_normal(float3 n, float3 toward) {
    float facing = dot(n, toward);
    if (facing >= MIN_FACING_COSINE) return n;
    return normalize(n + toward * (MIN_FACING_COSINE - facing));
}

/* Anisotropy follows the lines of latitude about +y: brushed metal on a shader ball is brushed round it. */
static ShadingFrame shading_frame(float3 n) { return frame_from_normal_tangent(n, make_float3(n.z, 0.0f, -n.x)); }

static float3 environment_from(const EnvironmentMap* env, EnvironmentBuffers buffers, float3 direction) {
    return environment_radiance(env, buffers.texels, direction);
}

/* What the camera sees directly or through mirrors only: filtered, so the backdrop shows no texels. */
static float3 environment_seen(const EnvironmentMap* env, EnvironmentBuffers buffers, float3 direction) {
    return environment_radiance_filtered(env, buffers.texels, direction);
}

/* Next-event estimation of the environment at a surface point: one environment sample, its shadow
 * ray, and the BSDF there. Returns the contribution before the path throughput. */
static float3 sample_environment_light(const PreviewSettings* s, const EnvironmentMap* env, EnvironmentBuffers buffers,
                                       const Material* m, ShadingFrame frame, float3 p, float3 wo, float epsilon,
                                       float2 u, PathCounters* counters) {
    float env_pdf;
    float3 wl = environment_sample(env, buffers.marginal_cdf, buffers.conditional_cdf, u.x, u.y, &env_pdf);
    if (!(env_pdf > 0.0f)) return float3_splat(0.0f);
    float3 wl_local = frame_to_local(frame, wl);
    float3 f = bsdf_eval(m, wo, wl_local);
    if (!(max_component(f) > 0.0f)) return float3_splat(0.0f);
    MarchResult shadow = march(offset_origin(p, frame.n, epsilon, wl_local.z), wl, 0.0f, s->march);
    counters->rays += 1u;
    if (shadow.status == MARCH_OUT_OF_STEPS) counters->lost_rays += 1u;
    if (shadow.status != MARCH_MISS) return float3_splat(0.0f);
    float weight = s->k.strategy == IBL_SAMPLING_MIS ? mis_power_heuristic(env_pdf, bsdf_pdf(m, wo, wl_local)) : 1.0f;
    return f * environment_from(env, buffers, wl) * (fabs(wl_local.z) * weight / env_pdf);
}

static float3 trace_path(const PreviewSettings* s, const EnvironmentMap* env, EnvironmentBuffers buffers,
                         GLOBAL_MEM const Material* materials, GLOBAL_MEM const float4* emission, float3 origin,
                         float3 direction, Rng* rng, PathCounters* counters) {
    float3 radiance = float3_splat(0.0f);
    float3 throughput = float3_splat(1.0f);
    float previous_pdf = 0.0f;
    bool previous_delta = true; /* the camera ray: nothing else could have found what it sees */
    bool seen_directly = true;  /* the camera ray, or only delta events since */
    bool inside = scene_distance(origin) < 0.0f; /* in a solid: only transmission gets a ray there */
    for (int depth = 0;; ++depth) {
        MarchResult hit = march(origin, direction, 0.0f, s->march);
        counters->rays += 1u;
        if (hit.status != MARCH_HIT) {
            if (hit.status == MARCH_OUT_OF_STEPS) counters->lost_rays += 1u;
            float weight = 1.0f;
            if (!previous_delta && s->k.strategy == IBL_SAMPLING_ENV) weight = 0.0f;
            if (!previous_delta && s->k.strategy == IBL_SAMPLING_MIS)
                weight = mis_power_heuristic(previous_pdf, environment_pdf(env, buffers.marginal_cdf, buffers.conditional_cdf, direction));
            if (weight > 0.0f)
                radiance += throughput * weight *
                            (seen_directly ? environment_seen(env, buffers, direction) : environment_from(env, buffers, direction));
            break;
        }
        float3 p = origin + direction * hit.t;
        int slot = 0;
        scene_distance_material(p, &slot);
        float4 emitted = emission[slot];
        if (emitted.w > 0.0f) { /* an emissive sphere: a pure emitter, it reflects nothing */
            radiance += throughput * make_float3(emitted.x, emitted.y, emitted.z);
            break;
        }
        if (depth >= s->k.max_depth) break;

        Material m = materials[slot]; /* bsdf_* take private pointers */
        float3 outward = scene_normal(p, s->k.normal_step, s->k.normal_method);
        /* the frame's normal stays outward (the BSDF tells the sides apart); the side the ray came from must face it */
        ShadingFrame frame = shading_frame(inside ? -facing_normal(-outward, -direction) : facing_normal(outward, -direction));
        float3 wo = frame_to_local(frame, -direction);
        float epsilon = march_epsilon(s->march, hit.t); /* the scale of the error in p */

        float4 u_light = rng_next4(rng);
        float4 u_bsdf = rng_next4(rng);
        if (s->k.strategy != IBL_SAMPLING_BRDF)
            radiance += throughput * sample_environment_light(s, env, buffers, &m, frame, p, wo, epsilon,
                                                              make_float2(u_light.x, u_light.y), counters);

        BsdfSample b = bsdf_sample(&m, wo, make_float3(u_bsdf.x, u_bsdf.y, u_bsdf.z));
        if (b.flags == 0) break;
        throughput *= b.f * (fabs(b.wi.z) / b.pdf);
        previous_pdf = b.pdf;
        previous_delta = (b.flags & BSDF_DELTA) != 0;
        seen_directly = seen_directly && previous_delta;
        if ((b.flags & BSDF_TRANSMISSION) != 0) inside = !inside;
        origin = offset_origin(p, frame.n, epsilon, b.wi.z);
        direction = frame_to_world(frame, b.wi);

        /* Russian roulette keeps a path with probability min(1, max throughput): a path whose
         * throughput stays 1 (white furnace) is never cut, so the estimator's variance is not raised
         * where nothing is absorbed. */
        if (depth + 1 >= s->k.roulette_depth) {
            float survive = fmin(max_component(throughput), 1.0f);
            if (!(u_light.z < survive)) break;
            throughput /= survive;
        }
    }
    return radiance;
}

/* One work-item per pixel; pixel k is (k % width, k / width), row 0 at the top. accumulation.xyz
 * sums the finite samples, accumulation.w counts the non-finite ones (reported, never hidden). */
__kernel void preview_render(PreviewKernelSettings kernel_settings, Camera camera, EnvironmentMap env,
                             __global const float4* env_texels, __global const float* env_marginal_cdf,
                             __global const float* env_conditional_cdf, __global const Material* materials,
                             __global const float4* emission, __global float4* accumulation, __global uint* ray_counts,
                             __global uint* lost_ray_counts) {
    int pixel = (int)get_global_id(0);
    if (pixel >= camera.width * camera.height) return;
    PreviewSettings settings = preview_settings(kernel_settings);
    EnvironmentBuffers buffers;
    buffers.texels = env_texels;
    buffers.marginal_cdf = env_marginal_cdf;
    buffers.conditional_cdf = env_conditional_cdf;
    float x = (float)(pixel % camera.width), y = (float)(pixel / camera.width);
    float4 sum = accumulation[pixel];
    PathCounters counters;
    counters.rays = 0u;
    counters.lost_rays = 0u;
    for (int k = 0; k < settings.k.sample_count; ++k) {
        Rng rng = rng_make((uint)pixel, (uint)(settings.k.first_sample + k), settings.k.seed_lo, settings.k.seed_hi);
        float4 u_pixel = rng_next4(&rng); /* box-filter jitter within the pixel */
        float3 origin, direction;
        camera_generate_ray(&camera, x + u_pixel.x, y + u_pixel.y, make_float2(u_pixel.z, u_pixel.w), &origin, &direction);
        float3 l = trace_path(&settings, &env, buffers, materials, emission, origin, direction, &rng, &counters);
        if (finite3(l)) sum += make_float4(l.x, l.y, l.z, 0.0f);
        else sum.w += 1.0f;
    }
    accumulation[pixel] = sum;
    ray_counts[pixel] += counters.rays;
    lost_ray_counts[pixel] += counters.lost_rays;
}
