/* The cube an environment is stored on: six square faces at distance 1 from the origin, each
 * N x N texels, following the OpenGL cube-map convention (OpenGL 4.6 core specification,
 * section 8.13, table 8.19), so the texel array uploads to a GL cube map face by face as is.
 *
 * Faces, in storage order: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
 * A direction d is on the face of its largest |component| m (ties go to x before y before z, and to
 * the face whose sign matches); its face coordinates are a = sc / |m|, b = tc / |m| in [-1, 1]:
 *
 *   face   sc    tc    direction of face point (a, b)
 *   +x     -z    -y    ( 1, -b, -a)
 *   -x     +z    -y    (-1, -b,  a)
 *   +y     +x    +z    ( a,  1,  b)
 *   -y     +x    -z    ( a, -1, -b)
 *   +z     +x    -y    ( a, -b,  1)
 *   -z     -x    -y    (-a, -b, -1)
 *
 * Texel (i, j) of a face covers a in [-1 + 2i/N, -1 + 2(i+1)/N] (column i) and
 * b in [-1 + 2j/N, -1 + 2(j+1)/N] (row j); it is stored at index (face * N + j) * N + i. In GL's
 * terms a = 2s - 1 and b = 2t - 1, and row j = 0 is the first row of the face's image data. On the
 * four side faces b = -1 is the top edge (towards +y).
 *
 * A point (a, b) on a face at distance 1 lies at distance r = sqrt(1 + a^2 + b^2) from the centre,
 * and the face's normal makes the angle theta with the ray, cos theta = 1 / r. The solid angle of a
 * small area dA there is dA cos theta / r^2 = dA / (1 + a^2 + b^2)^(3/2). */
#ifndef IBL_CUBEMAP_H
#define IBL_CUBEMAP_H

#include "single_source/vocabulary.h"

#define CUBEMAP_FACES 6

/* Face of direction d (any length but 0) and its face coordinates a, b in [-1, 1]:
 *   face 0 (+x): a = -z/|x|, b = -y/|x|     face 1 (-x): a = z/|x|,  b = -y/|x|
 *   face 2 (+y): a = x/|y|,  b = z/|y|      face 3 (-y): a = x/|y|,  b = -z/|y|
 *   face 4 (+z): a = x/|z|,  b = -y/|z|     face 5 (-z): a = -x/|z|, b = -y/|z|
 * the major axis winning ties in the order x, y, z. Written with selects, not branches: a path's
 * directions (light samples, rays leaving a surface) fall on the faces at random, which no branch
 * predictor foresees; the signs are exact, so the results are those of the branches. */
SS_FN int cubemap_face(float3 d, float* a, float* b) {
    float ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    bool x_major = ax >= ay && ax >= az;
    bool y_major = !x_major && ay >= az;
    float major = x_major ? d.x : (y_major ? d.y : d.z);
    bool positive = major >= 0.0f;
    float inv = 1.0f / (x_major ? ax : (y_major ? ay : az));
    float a_sign = x_major ? (positive ? -1.0f : 1.0f) : (y_major || positive ? 1.0f : -1.0f);
    float b_sign = y_major && positive ? 1.0f : -1.0f;
    *a = (a_sign * (x_major ? d.z : d.x)) * inv;
    *b = (b_sign * (y_major ? d.z : d.y)) * inv;
    return (x_major ? 0 : (y_major ? 2 : 4)) + (positive ? 0 : 1);
}

/* The point (a, b) of a face as a direction (not normalised: its length is sqrt(1 + a^2 + b^2)). */
SS_FN float3 cubemap_face_point(int face, float a, float b) {
    if (face == 0) return make_float3(1.0f, -b, -a);
    if (face == 1) return make_float3(-1.0f, -b, a);
    if (face == 2) return make_float3(a, 1.0f, b);
    if (face == 3) return make_float3(a, -1.0f, -b);
    if (face == 4) return make_float3(a, -b, 1.0f);
    return make_float3(-a, -b, -1.0f);
}

/* Column (or row) of the texel holding face coordinate a. Clamped, so a = 1 lands in the last
 * texel and a NaN (from a zero direction) in the first: every direction reads a valid texel. The
 * clamped x is >= 0, where truncation is floor: (int) alone, without PoCL's out-of-range checks
 * of floor (the same bits). */
SS_FN int cubemap_texel_coordinate(int face_size, float a) {
    float x = (a + 1.0f) * 0.5f * (float)face_size;
    return (int)fmin(fmax(x, 0.0f), (float)(face_size - 1));
}

/* Index of the texel direction d falls into, and d's face coordinates a, b. */
SS_FN int cubemap_texel(int face_size, float3 d, float* a, float* b) {
    int face = cubemap_face(d, a, b);
    int i = cubemap_texel_coordinate(face_size, *a);
    int j = cubemap_texel_coordinate(face_size, *b);
    return (face * face_size + j) * face_size + i;
}

/* Index of the texel direction d falls into. */
SS_FN int cubemap_texel_index(int face_size, float3 d) {
    float a, b;
    return cubemap_texel(face_size, d, &a, &b);
}

/* dA / d(solid angle) at face point (a, b): (1 + a^2 + b^2)^(3/2) (see the top of this file). */
SS_FN float cubemap_area_per_solid_angle(float a, float b) {
    float r2 = 1.0f + a * a + b * b;
    return r2 * sqrt(r2);
}

#endif
