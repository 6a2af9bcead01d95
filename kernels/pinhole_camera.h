/* The pinhole camera: primary rays through a pixel position (jittered by the caller). Plain float
 * arrays, not float3, so the struct has one layout on the host and in OpenCL C and travels as a
 * kernel argument by value. */
#ifndef KERNELS_PINHOLE_CAMERA_H
#define KERNELS_PINHOLE_CAMERA_H
#include "single_source/vocabulary.h"

typedef struct PinholeCamera {
    float position[3];
    float forward[3]; /* unit view direction */
    float right[3];   /* scaled to the image's half width at distance 1: tan(fov / 2) * aspect */
    float up[3];      /* scaled to the image's half height at distance 1: tan(fov / 2) */
    int width, height;
} PinholeCamera;

SS_FN float3 camera_vector(const float v[3]) { return make_float3(v[0], v[1], v[2]); }

/* (x, y) in pixels from the top-left image corner; the image centre looks down `forward`. */
SS_FN float3 pinhole_ray_direction(const PinholeCamera* c, float x, float y) {
    float sx = 2.0f * x / (float)c->width - 1.0f;
    float sy = 1.0f - 2.0f * y / (float)c->height;
    return normalize(camera_vector(c->forward) + sx * camera_vector(c->right) + sy * camera_vector(c->up));
}

#endif
