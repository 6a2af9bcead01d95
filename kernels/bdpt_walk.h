/* BDPT's subpaths (after pbrt-v4's GenerateCameraSubpath, GenerateLightSubpath and RandomWalk): a
 * camera subpath from the lens, a light subpath from a point on a light, each extended by BSDF
 * sampling in its own transport mode, recording the forward density of every vertex and the
 * reverse density of the one before it. Needs the scene declared before it, as kernels/path.h does. */
#ifndef KERNELS_BDPT_WALK_H
#define KERNELS_BDPT_WALK_H

#include "kernels/bdpt_vertex.h"
#include "kernels/rng.h"

/* Extends `path` (count vertices so far, the last one the ray's origin) by the ray from origin
 * along unit `direction` that carries throughput beta and was sampled with solid-angle density
 * pdf_dir, up to max_count vertices. A camera subpath that escapes ends on the environment (when
 * there is one). Russian roulette from settings->roulette_depth scattering events on keeps a subpath with
 * probability min(1, max beta / max beta at its start). Returns the new count. */
SS_FN int bdpt_random_walk(const RenderKernelSettings* settings, MarchSettings march_settings, const RenderScene* scene, Rng* rng, float3 origin,
                           float3 direction, float3 beta, float pdf_dir, int mode, bool inside, PathVertex* path, int count,
                           int max_count, PathCounters* counters) {
    bool has_environment = settings->light_count > 0 && scene->lights[0].type == LIGHT_ENVIRONMENT;
    float beta_start = max_component(beta);
    for (int bounces = 0; count < max_count; ++bounces) {
        MarchResult r = trace_ray(origin, direction, march_settings, counters);
        PathVertex v;
        v.beta = beta;
        v.pdf_rev = 0.0f;
        v.delta = 0;
        if (r.status != MARCH_HIT) {
            if (mode != TRANSPORT_RADIANCE || !has_environment) break;
            v.type = VERTEX_ENVIRONMENT;
            v.p = direction;
            v.frame = frame_from_normal(-direction);
            v.wo = make_float3(0.0f, 0.0f, 1.0f);
            v.epsilon = 0.0f;
            v.index = 0;
            v.on_surface = 0;
            v.pdf_fwd = pdf_dir; /* a density at infinity stays per solid angle */
            path[count++] = v;
            break;
        }
        SurfaceHit hit = surface_hit(settings, march_settings, origin, direction, r.t, inside);
        /* an emitter scatters on the side the ray arrives from, outside or in (kernels/path_tracer.h) */
        if (scene->emission[hit.slot].w > 0.0f && scene->emission[hit.slot].w != EMISSION_SURFACE) hit = facing_side(hit);
        v.type = VERTEX_SURFACE;
        v.p = hit.p;
        v.frame = hit.frame;
        v.wo = hit.wo;
        v.epsilon = hit.epsilon;
        v.index = hit.slot;
        v.on_surface = 1;
        v.pdf_fwd = vertex_convert_density(pdf_dir, &path[count - 1], &v);
        path[count++] = v;
        if (count >= max_count || !vertex_scatters(scene, &v)) break;

        Material m = scene->materials[hit.slot];
        float4 u = rng_next4(rng);
        BsdfSample b = bsdf_sample_mode(&m, scene->tables, hit.wo, make_float3(u.x, u.y, u.z), mode);
        if (b.flags == 0 || !(b.pdf > 0.0f)) break;
        float pdf_rev_dir = bsdf_pdf_clamped(&m, scene->tables, b.wi, hit.wo);
        if ((b.flags & BSDF_DELTA) != 0) { /* no other strategy samples a delta lobe: densities 0, remapped by the weights */
            path[count - 1].delta = 1;
            pdf_rev_dir = 0.0f;
            pdf_dir = 0.0f;
        } else {
            pdf_dir = b.pdf;
        }
        beta *= b.f * (fabs(b.wi.z) / b.pdf);
        path[count - 2].pdf_rev = vertex_convert_density(pdf_rev_dir, &path[count - 1], &path[count - 2]);
        if ((b.flags & BSDF_TRANSMISSION) != 0) inside = !inside;
        origin = offset_origin(hit.p, hit.frame.n, hit.epsilon, b.wi.z);
        direction = frame_to_world(hit.frame, b.wi);
        if (bounces + 1 >= settings->roulette_depth) {
            float survive = fmin(max_component(beta) / beta_start, 1.0f);
            if (!(u.w < survive)) break;
            beta /= survive;
        }
    }
    return count;
}

/* The camera subpath of pixel `pixel`, its ray drawn as the path tracer draws it (camera_pixel_ray):
 * the lens vertex, then the walk in radiance mode. */
SS_FN int bdpt_camera_subpath(const RenderKernelSettings* settings, MarchSettings march_settings, const Camera* camera, const RenderScene* scene, int pixel,
                              Rng* rng, PathVertex* path, int max_count, PathCounters* counters) {
    float3 origin, direction;
    camera_pixel_ray(camera, pixel, rng, &origin, &direction);
    /* beta: W_e / (pdf_position pdf_direction) = 1 for the box filter */
    path[0] = camera_vertex(camera, origin, float3_splat(1.0f));
    float pdf_position, pdf_direction;
    camera_pdf_we(camera, origin, direction, &pdf_position, &pdf_direction);
    bool inside = scene_distance(origin) < 0.0f;
    return bdpt_random_walk(settings, march_settings, scene, rng, origin, direction, float3_splat(1.0f), pdf_direction, TRANSPORT_RADIANCE, inside, path, 1,
                            max_count, counters);
}

/* The light subpath: a light chosen by the selection distribution, a point and direction on it,
 * then the walk in importance mode.
 *   sphere: a point uniform by area, a cosine-distributed direction on a side chosen with
 *           probability 1/2 (it emits from both), pdf_dir = |cos| / (2 pi);
 *   rect, disk: a point uniform by area, a cosine-distributed direction on its emitting side,
 *           pdf_dir = cos / pi;
 *   point:  a direction uniform on the sphere;
 *   environment: a direction from its importance sampler, the origin uniform on a disk of the
 *           scene's radius facing it (pbrt-v4's ImageInfiniteLight::SampleLe). */
SS_FN int bdpt_light_subpath(const RenderKernelSettings* settings, MarchSettings march_settings, const RenderScene* scene, Rng* rng, PathVertex* path,
                             int max_count, PathCounters* counters) {
    float4 u = rng_next4(rng);
    float4 u_dir = rng_next4(rng);
    float pmf;
    int index = select_light(scene->light_cdf, settings->light_count, u.x, &pmf);
    if (!(pmf > 0.0f) || max_count < 1) return 0;
    Light light = scene->lights[index];
    PathVertex v;
    v.type = VERTEX_LIGHT;
    v.index = index;
    v.wo = make_float3(0.0f, 0.0f, 1.0f);
    v.pdf_rev = 0.0f;
    v.delta = 0;
    v.on_surface = 0;
    v.epsilon = march_epsilon(march_settings, 0.0f);
    float3 origin, direction, le;
    float pdf_position, pdf_dir, cos_out = 1.0f;
    if (light_is_surface(light.type)) {
        float3 n;
        v.p = light_sample_area(&light, scene->env_buffers, make_float2(u.y, u.z), &n);
        v.frame = frame_from_normal(n);
        v.on_surface = 1;
        /* a sphere emits from both sides, each chosen with probability 1/2; a rect or disk from its
         * emitting side */
        bool two_sided = light.type == LIGHT_SPHERE;
        ShadingFrame side = frame_from_normal(two_sided && u_dir.z >= 0.5f ? -n : n);
        float3 w_local = square_to_cosine_hemisphere(u_dir.x, u_dir.y);
        direction = frame_to_world(side, w_local);
        cos_out = w_local.z;
        pdf_dir = w_local.z * (two_sided ? 0.5f * SS_INV_PI : SS_INV_PI);
        pdf_position = light_area_pdf(&light, scene->env_buffers, v.p);
        /* the offset's floor: a relative 1e-5 of the light's size (its radius, or a rect's edge) */
        float size = light.type == LIGHT_RECT ? fmin(length(area_light_u(&light)), length(area_light_v(&light))) : light.radius;
        origin = offset_origin(v.p, side.n, fmax(v.epsilon, 1e-5f * size), 1.0f);
        /* Le, or an image's texel at the point (along n: its emitting side) */
        le = light_has_image(&light) ? light_surface_radiance(&light, scene->env_buffers, v.p, n) : float3_from_array(light.emission);
    } else if (light.type == LIGHT_POINT) {
        v.p = float3_from_array(light.position);
        v.frame = frame_from_normal(make_float3(0.0f, 0.0f, 1.0f));
        direction = square_to_uniform_sphere(u_dir.x, u_dir.y);
        pdf_dir = SS_INV_4PI;
        pdf_position = 1.0f;
        origin = v.p;
        le = float3_from_array(light.emission);
    } else {
        EnvironmentBuffers eb = scene->env_buffers;
        float3 wi = environment_sample(&scene->env, eb.texels, eb.alias, u_dir.x, u_dir.y, &pdf_dir);
        if (!(pdf_dir > 0.0f)) return 0;
        v.type = VERTEX_ENVIRONMENT;
        v.p = wi;
        v.frame = frame_from_normal(-wi);
        ShadingFrame disk_frame = frame_from_normal(wi);
        float2 d = square_to_concentric_disk(u.y, u.z) * settings->bdpt.scene_radius;
        float3 center = float3_from_array(settings->bdpt.scene_center);
        origin = center + d.x * disk_frame.t + d.y * disk_frame.b + wi * settings->bdpt.scene_radius;
        direction = -wi;
        pdf_position = 1.0f / (SS_PI * sqr(settings->bdpt.scene_radius));
        le = environment_radiance(&scene->env, scene->env_buffers.texels, wi);
    }
    if (!(pdf_dir > 0.0f) || !(pdf_position > 0.0f)) return 0;
    v.beta = le / (pmf * pdf_position);
    v.pdf_fwd = v.type == VERTEX_ENVIRONMENT ? pmf * pdf_dir : pmf * pdf_position;
    path[0] = v;
    float3 beta = le * (cos_out / (pmf * pdf_position * pdf_dir));
    bool inside = scene_distance(origin) < 0.0f;
    /* a disk point inside a solid (an endless plane crosses the disk) lies in the solid's shadow:
     * nothing its ray reaches is lit along it */
    if (v.type == VERTEX_ENVIRONMENT && inside) return 1;
    int count = bdpt_random_walk(settings, march_settings, scene, rng, origin, direction, beta, pdf_dir, TRANSPORT_IMPORTANCE, inside, path, 1, max_count,
                                 counters);
    /* from the environment the first hit's density is the disk's, per unit area across the ray */
    if (v.type == VERTEX_ENVIRONMENT && count > 1)
        path[1].pdf_fwd = pdf_position * (path[1].on_surface ? fabs(dot(path[1].frame.n, v.p)) : 1.0f);
    return count;
}

#endif
