/* Trivial stand-ins for one part of the path tracer at a time, for `dtoadq bench breakdown`: a
 * build with -DBENCH_STANDIN_RNG, _ENVIRONMENT or _BSDF replaces that part by something nearly free,
 * and the change in paths/s against the default build, in the same run, bounds the part's share of
 * the time. -DBENCH_TWICE_ENVIRONMENT instead does the environment's part twice, keeping the paths
 * (see there). Included only by the measurement builds' program, bench/kernels/path_tracer_standins.cl,
 * before kernels/path_tracer.h: it first includes every header kernels/path_tracer.h includes, so
 * that, by their include guards, only the path tracer's own calls are redirected. A stand-in changes the
 * random numbers or the light transport, so the paths differ (the bench prints rays per path of
 * each build next to its paths/s); never for images. */
#ifndef BENCH_KERNELS_PART_STANDINS_H
#define BENCH_KERNELS_PART_STANDINS_H

#include "single_source/vocabulary.h"
#include "brdf/bsdf.h"
#include "brdf/warp.h"
#include "ibl/environment.h"
#include "kernels/camera.h"
#include "kernels/lights/light_selection.h"
#include "kernels/mis.h"
#include "kernels/path.h"
#include "kernels/render_scene.h"
#include "kernels/rng.h"

#ifdef BENCH_STANDIN_RNG
/* One multiply-xorshift hash per path in place of the Philox call that seeds it, and one per number
 * in place of the xoshiro steps. */
SS_FN uint standin_hash(uint x) {
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    return x;
}
SS_FN Rng standin_rng_make(uint pixel, uint sample, uint seed_lo, uint seed_hi) {
    Rng r;
    r.s0 = standin_hash(pixel * 0x9E3779B9u ^ sample * 0x85EBCA6Bu ^ seed_lo ^ seed_hi * 0xC2B2AE35u);
    r.s1 = 0u; /* the draw */
    r.s2 = 0u;
    r.s3 = 0u;
    return r;
}
SS_FN float4 standin_rng_next4(Rng* r) {
    uint h = standin_hash(r->s0 ^ r->s1 * 0xC2B2AE35u);
    r->s1 += 1u;
    uint a = standin_hash(h + 1u), b = standin_hash(h + 2u), c = standin_hash(h + 3u), d = standin_hash(h + 4u);
    return make_float4(uint_to_unit_float(a), uint_to_unit_float(b), uint_to_unit_float(c), uint_to_unit_float(d));
}
#define rng_make(pixel, sample, seed_lo, seed_hi) standin_rng_make(pixel, sample, seed_lo, seed_hi)
#define rng_next4(r) standin_rng_next4(r)
#endif

#ifdef BENCH_STANDIN_ENVIRONMENT
/* The environment sampled uniformly over the sphere: no cdf inversion, no pdf lookup (the radiance
 * lookup stays). Other lights as before. */
SS_FN LightSample standin_sample_light(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float2 u) {
    if (l->type != LIGHT_ENVIRONMENT) return sample_light(l, env, b, p, u);
    LightSample s = light_sample_none();
    s.wi = square_to_uniform_sphere(u.x, u.y);
    s.distance = LIGHT_INFINITE_DISTANCE;
    s.radiance = environment_radiance(env, b.texels, s.wi);
    s.pdf = 0.25f * SS_INV_PI;
    s.position = s.wi;
    s.normal = -s.wi;
    return s;
}
SS_FN float standin_light_pdf(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float3 wi) {
    return l->type == LIGHT_ENVIRONMENT ? 0.25f * SS_INV_PI : light_pdf(l, env, b, p, wi);
}
#define sample_light(l, env, b, p, u) standin_sample_light(l, env, b, p, u)
#define light_pdf(l, env, b, p, wi) standin_light_pdf(l, env, b, p, wi)
#endif

#ifdef BENCH_TWICE_ENVIRONMENT
/* Every environment sample and pdf evaluated a second time, on another direction (so that the
 * compiler cannot reuse the first), its result added times 0 (kept: 0 x a float is not 0 without
 * relaxed math). The paths stay exactly those of the default build, unlike with the stand-in
 * above, whose uniform directions point below the surface half the time and so skip shadow rays:
 * paths/s(default) / paths/s(twice) - 1 is at most the environment's share of the time, since the
 * path tracer's peeks ask the cache for the first lookups ahead (kernels/path_tracer_wavefront.h)
 * and not for these. */
SS_FN LightSample twice_sample_light(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float2 u) {
    LightSample s = sample_light(l, env, b, p, u);
    if (l->type == LIGHT_ENVIRONMENT) {
        LightSample again = sample_light(l, env, b, p, make_float2(u.y, u.x));
        s.pdf += 0.0f * again.pdf * again.radiance.x;
    }
    return s;
}
SS_FN float twice_light_pdf(const Light* l, const EnvironmentMap* env, EnvironmentBuffers b, float3 p, float3 wi) {
    float pdf = light_pdf(l, env, b, p, wi);
    return l->type == LIGHT_ENVIRONMENT ? pdf + 0.0f * light_pdf(l, env, b, p, make_float3(wi.y, wi.z, wi.x)) : pdf;
}
#define sample_light(l, env, b, p, u) twice_sample_light(l, env, b, p, u)
#define light_pdf(l, env, b, p, wi) twice_light_pdf(l, env, b, p, wi)
#endif

#ifdef BENCH_STANDIN_BSDF
/* A grey Lambert reflector (albedo 0.8) in place of every material. */
#define STANDIN_ALBEDO 0.8f
SS_FN float3 standin_bsdf_eval(float3 wo, float3 wi) {
    return float3_splat(wo.z > 0.0f && wi.z > 0.0f ? STANDIN_ALBEDO * SS_INV_PI : 0.0f);
}
SS_FN float standin_bsdf_pdf(float3 wo, float3 wi) { return wo.z > 0.0f ? cosine_hemisphere_pdf(wi.z) : 0.0f; }
SS_FN BsdfSample standin_bsdf_sample(float3 wo, float3 u) {
    if (!(wo.z > 0.0f)) return bsdf_sample_failed();
    BsdfSample s;
    s.wi = square_to_cosine_hemisphere(u.y, u.z);
    s.pdf = cosine_hemisphere_pdf(s.wi.z);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.f = float3_splat(STANDIN_ALBEDO * SS_INV_PI);
    s.flags = BSDF_REFLECTION;
    return s;
}
/* the path tracer calls the *_clamped forms (the renderer clamped its materials once) */
#define bsdf_eval_clamped(m, measured, wo, wi) standin_bsdf_eval(wo, wi)
#define bsdf_pdf_clamped(m, measured, wo, wi) standin_bsdf_pdf(wo, wi)
#define bsdf_sample_clamped(m, measured, wo, u) standin_bsdf_sample(wo, u)
#endif

#endif
