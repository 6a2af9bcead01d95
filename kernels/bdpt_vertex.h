/* A vertex of a BDPT subpath and the densities BDPT's MIS weights are made of, after pbrt-v4's
 * Vertex (docs/bdpt.md). Densities are per unit area at the vertex they lead to (times |cos| there
 * when it lies on a surface), except where a vertex lies at infinity (the environment): there they
 * stay per unit solid angle. Needs the scene declared before it, as kernels/path.h does. */
#ifndef KERNELS_BDPT_VERTEX_H
#define KERNELS_BDPT_VERTEX_H

#include "single_source/vocabulary.h"
#include "brdf/bsdf_transport.h"
#include "kernels/camera.h"
#include "kernels/lights/light_selection.h"
#include "kernels/path.h"
#include "kernels/render_scene.h"

#define VERTEX_CAMERA 0      /* the lens point (the camera position for a pinhole) */
#define VERTEX_LIGHT 1       /* a point on a sphere light or a point light: a light subpath's origin or a light sample */
#define VERTEX_SURFACE 2     /* a scattering point; an emissive sphere the camera subpath hits is one too */
#define VERTEX_ENVIRONMENT 3 /* the environment, at infinity: p holds the unit direction towards it */

/* The largest subpath, in vertices, a kernel has room for (private arrays of fixed size): an OpenCL
 * build defines it as its settings' max_vertices (render/opencl_renderer.cpp). */
#ifndef BDPT_MAX_VERTICES
#define BDPT_MAX_VERTICES BDPT_VERTEX_LIMIT
#endif

typedef struct PathVertex {
    float3 p;
    ShadingFrame frame; /* surfaces and sphere lights: frame.n the normal (the SDF's, geometric = shading) */
    float3 wo;          /* surfaces: towards the previous vertex, in the frame */
    float3 beta;        /* the subpath's throughput up to here (light vertices: Le / (pmf pdf_position)) */
    float pdf_fwd;      /* density of this vertex as its own subpath sampled it */
    float pdf_rev;      /* density of this vertex as the other subpath would sample it */
    float epsilon;      /* surfaces: the march's error scale at p */
    int type;           /* VERTEX_* */
    int index;          /* surfaces: material slot; lights: the light's index */
    int delta;          /* surfaces: left by a delta lobe */
    int on_surface;     /* has a normal a density converts with (surfaces, sphere lights) */
} PathVertex;

/* A vertex on the camera's lens at p, facing along the camera's axis, with throughput beta. */
SS_FN PathVertex camera_vertex(const Camera* camera, float3 p, float3 beta) {
    PathVertex c;
    c.type = VERTEX_CAMERA;
    c.p = p;
    c.frame = frame_from_normal(float3_from_array(camera->forward));
    c.wo = make_float3(0.0f, 0.0f, 1.0f);
    c.beta = beta;
    c.pdf_fwd = 0.0f;
    c.pdf_rev = 0.0f;
    c.epsilon = 0.0f;
    c.index = 0;
    c.delta = 0;
    c.on_surface = 0;
    return c;
}

SS_FN bool vertex_emits(const RenderScene* scene, const PathVertex* v) {
    if (v->type == VERTEX_SURFACE) return scene->emission[v->index].w > 0.0f;
    return v->type != VERTEX_CAMERA;
}

/* A surface that can scatter: not a black emitter, which absorbs everything. */
SS_FN bool vertex_scatters(const RenderScene* scene, const PathVertex* v) {
    return v->type == VERTEX_SURFACE && !(scene->emission[v->index].w > 0.0f && scene->emission[v->index].w < EMISSION_SCATTERS);
}

/* The light a vertex emits as: its own index, or the light of an emissive sphere's slot; -1 for a
 * material's emission, which is no light: no light subpath starts there, no light sample finds it. */
SS_FN int vertex_light_index(const RenderScene* scene, const PathVertex* v) {
    if (v->type == VERTEX_SURFACE) return scene->light_of_slot[v->index];
    return v->index;
}

/* Point lights are delta in position: no camera subpath can reach them. */
SS_FN bool vertex_is_delta_light(const RenderScene* scene, const PathVertex* v) {
    return v->type == VERTEX_LIGHT && scene->lights[v->index].type == LIGHT_POINT;
}

/* Unit direction from v towards w (either may lie at infinity). */
SS_FN float3 vertex_direction(const PathVertex* v, const PathVertex* w) {
    if (w->type == VERTEX_ENVIRONMENT) return w->p;
    if (v->type == VERTEX_ENVIRONMENT) return -v->p;
    return normalize(w->p - v->p);
}

/* A solid-angle density at `from` of the direction towards `to`, as a density at `to`. */
SS_FN float vertex_convert_density(float pdf, const PathVertex* from, const PathVertex* to) {
    if (to->type == VERTEX_ENVIRONMENT) return pdf;
    float3 w = to->p - from->p;
    float d2 = dot(w, w);
    if (!(d2 > 0.0f)) return 0.0f;
    float inv_d = 1.0f / sqrt(d2);
    if (to->on_surface) pdf *= fabs(dot(to->frame.n, w * inv_d));
    return pdf * inv_d * inv_d;
}

/* pmf times the density with which a light subpath starts at v: per unit area on an emitter,
 * 1 for a point light (a delta position), per unit solid angle of the direction for the environment
 * (pbrt-v4's PdfLightOrigin). */
SS_FN float vertex_pdf_light_origin(const RenderKernelSettings* settings, const RenderScene* scene, const PathVertex* v) {
    int index = vertex_light_index(scene, v);
    if (index < 0) return 0.0f;
    float pmf = light_selection_pmf(scene->light_cdf, settings->light_count, index);
    if (!(pmf > 0.0f)) return 0.0f;
    Light light = scene->lights[index];
    if (light_is_surface(light.type)) return pmf * light_area_pdf(&light, scene->env_buffers, v->p);
    if (light.type == LIGHT_POINT) return pmf;
    return pmf * environment_light_pdf(&scene->env, scene->env_buffers, v->p);
}

/* The density per unit area across the ray with which an environment light subpath from
 * direction w (towards the environment) reaches point p: its rays start uniformly on the disk of the
 * scene's radius R that faces the scene from c + R w (bdpt_light_subpath) and run along -w for at most
 * the march's max_distance. A point outside that cylinder, above the disk or farther from it than a
 * ray runs is reached by no light subpath: its density is 0, so the strategies that start there take
 * no share of its paths' MIS weights. */
SS_FN float environment_disk_pdf(const RenderKernelSettings* settings, float3 w, float3 p) {
    float3 d = p - float3_from_array(settings->bdpt.scene_center);
    float along = dot(d, w);
    float3 across = d - along * w;
    float r2 = sqr(settings->bdpt.scene_radius);
    if (dot(across, across) > r2 || along > settings->bdpt.scene_radius || settings->bdpt.scene_radius - along > settings->max_distance) return 0.0f;
    return 1.0f / (SS_PI * r2);
}

/* The density at `next` of a light subpath leaving light vertex v towards it (pbrt-v4's
 * PdfLight): a sphere emits from both sides, cosine-distributed on each, a rect or disk from its
 * emitting side, cosine-distributed; a point light uniformly;
 * the environment from a disk of the scene's radius, uniform by area where its rays reach. */
SS_FN float vertex_pdf_light(const RenderKernelSettings* settings, const RenderScene* scene, const PathVertex* v, const PathVertex* next) {
    int index = vertex_light_index(scene, v);
    if (index < 0) return 0.0f; /* a material's emission: no light subpath leaves it */
    Light light = scene->lights[index];
    if (light.type == LIGHT_ENVIRONMENT) {
        float pdf = environment_disk_pdf(settings, v->p, next->p);
        return next->on_surface ? pdf * fabs(dot(next->frame.n, v->p)) : pdf;
    }
    float3 w = vertex_direction(v, next);
    float pdf_dir = SS_INV_4PI; /* a point light */
    if (light.type == LIGHT_SPHERE) pdf_dir = fabs(dot(v->frame.n, w)) * (0.5f * SS_INV_PI);
    else if (light_is_surface(light.type)) pdf_dir = fmax(dot(area_light_normal(&light), w), 0.0f) * SS_INV_PI;
    return vertex_convert_density(pdf_dir, v, next);
}

/* The density at `next` of v sampling it, coming from `prev` (ignored by the camera and lights). */
SS_FN float vertex_pdf(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* prev,
                       const PathVertex* v, const PathVertex* next) {
    if (v->type == VERTEX_CAMERA) {
        float pdf_position, pdf_direction;
        camera_pdf_we(camera, v->p, vertex_direction(v, next), &pdf_position, &pdf_direction);
        return vertex_convert_density(pdf_direction, v, next);
    }
    if (v->type != VERTEX_SURFACE) return vertex_pdf_light(settings, scene, v, next);
    Material m = scene->materials[v->index];
    float3 wp = frame_to_local(v->frame, vertex_direction(v, prev));
    float3 wn = frame_to_local(v->frame, vertex_direction(v, next));
    return vertex_convert_density(bsdf_pdf_clamped(&m, scene->tables, wp, wn), v, next);
}

/* f at surface vertex v between its previous vertex and unit world direction w, in the subpath's
 * transport mode; 0 at surfaces that do not scatter. The caller passes the direction it sampled or
 * connected along: one rebuilt from two nearly equal points would be noise. */
SS_FN float3 vertex_f(const RenderScene* scene, const PathVertex* v, float3 w, int mode) {
    if (!vertex_scatters(scene, v)) return float3_splat(0.0f);
    Material m = scene->materials[v->index];
    return bsdf_eval_mode(&m, scene->tables, v->wo, frame_to_local(v->frame, w), mode);
}

/* Radiance emitted by light or emitter vertex v towards its wo: a sphere's Le from both sides, a
 * rect's or disk's on its emitting side only, a material's emission towards wo on its outer side,
 * the environment's along the direction (the filtered lookup where the eye sees it directly). */
SS_FN float3 vertex_le(const RenderScene* scene, const PathVertex* v, bool seen_directly) {
    if (v->type == VERTEX_ENVIRONMENT)
        return seen_directly ? environment_radiance_filtered(&scene->env, scene->env_buffers.texels, v->p)
                             : environment_radiance(&scene->env, scene->env_buffers.texels, v->p);
    if (v->type == VERTEX_SURFACE) {
        float4 e = scene->emission[v->index];
#if BRDF_FEATURE_EMISSION
        if (e.w == EMISSION_SURFACE) { /* on the outer side only: wo is below the surface from inside */
            Material m = scene->materials[v->index];
            return material_emission_clamped(&m, v->wo);
        }
#endif
        int index = scene->light_of_slot[v->index];
        if (index < 0) return make_float3(e.x, e.y, e.z);
        Light light = scene->lights[index];
        return light_surface_radiance(&light, scene->env_buffers, v->p, frame_to_world(v->frame, v->wo));
    }
    Light light = scene->lights[v->index]; /* float3_from_array takes a private pointer */
    if (light_is_surface(light.type)) return light_surface_radiance(&light, scene->env_buffers, v->p, frame_to_world(v->frame, v->wo));
    return float3_from_array(light.emission);
}

#endif
