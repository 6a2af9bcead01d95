/* Lights: what every integrator (path tracer, light tracer, BDPT) knows about one light, and what a
 * sample of it returns. docs/lights.md gives the formulas and the power used for light selection.
 *
 * A Light is a plain struct of 4-byte scalars (16 words, 64 bytes): the same layout in OpenCL C and
 * C++, so the host uploads an array of them (render/light_set.hpp) as a buffer. The samplers take
 * private pointers: a kernel copies the light first (`Light l = lights[k];`). */
#ifndef KERNELS_LIGHTS_LIGHT_H
#define KERNELS_LIGHTS_LIGHT_H
#include "single_source/vocabulary.h"

#define LIGHT_ENVIRONMENT 0 /* the environment map at infinity (ibl/environment.h) */
#define LIGHT_SPHERE 1      /* an emissive sphere of the scene: part of the distance field */
#define LIGHT_POINT 2       /* a point light: a delta position, not geometry */
#define LIGHT_RECT 3        /* a rect emitter: a parallelogram emitting on one side, intersected exactly */
#define LIGHT_DISK 4        /* a disk emitter: emitting on the side of its normal, intersected exactly */
/* No kind of its own: the bit (1 << LIGHT_IMAGE) of SCENE_LIGHT_TYPES (kernels/lights/light_selection.h)
 * that says a scene has rects or disks showing an image (kernels/lights/image_emitter.h). */
#define LIGHT_IMAGE 5

/* The distance reported for a sample of the environment: far beyond any scene, yet finite, so a
 * shadow ray's maximum distance and comparisons stay well defined. */
#define LIGHT_INFINITE_DISTANCE 1e30f

typedef struct Light {
    float position[3]; /* sphere, rect, disk: its centre; point light: its position; environment: unused */
    float radius;      /* sphere, disk */
    float emission[3]; /* sphere, rect, disk: radiance Le, W m^-2 sr^-1 (a sphere's the same from both
                          sides, a rect's and a disk's on their emitting side only; with an image,
                          the RGB scale of its texels);
                          point light: intensity I, W sr^-1; environment: unused (the map holds it) */
    int type;          /* LIGHT_* */
    float edge_u[3];   /* rect: its edges U, V (the points centre + x U + y V, |x|, |y| <= 1/2,
                          emitting towards U x V); disk: its tangents times the radius (the points
                          centre + x U + y V, x^2 + y^2 <= 1, emitting towards U x V) */
    int material_slot; /* sphere, rect, disk: its material slot in the compiled scene; -1 otherwise */
    float edge_v[3];
    int image;         /* rect, disk showing an image (kernels/lights/image_emitter.h): the offset of
                          its header in the environment's alias buffer; 0: none (offset 0 is the
                          environment's own table) */
} Light;

/* One sample of one light, seen from a reference point p. */
typedef struct LightSample {
    float3 wi;        /* unit, from p towards the light */
    float distance;   /* from p to the sampled point; LIGHT_INFINITE_DISTANCE for the environment */
    float3 radiance;  /* what arrives at p along -wi before any BSDF or cosine: Le, or I / d^2 */
    float pdf;        /* solid-angle density of wi at p for this light alone (selection excluded);
                         1 for a point light (delta = 1); 0: no sample (skip it) */
    float3 position;  /* the sampled point on the light (BDPT's area densities); for the
                         environment, the direction wi itself (a point at infinity) */
    float3 normal;    /* the light's outward unit normal there; -wi for a point light and the environment */
    int delta;        /* 1: a delta distribution (point light), no MIS against BSDF sampling */
} LightSample;

SS_FN LightSample light_sample_none(void) {
    LightSample s;
    s.wi = make_float3(0.0f, 0.0f, 1.0f);
    s.distance = 0.0f;
    s.radiance = float3_splat(0.0f);
    s.pdf = 0.0f;
    s.position = float3_splat(0.0f);
    s.normal = make_float3(0.0f, 0.0f, 1.0f);
    s.delta = 0;
    return s;
}

#endif
