/* Image-based lighting from an environment stored as a cube map (ibl/cubemap.h), with importance
 * sampling of its texels (ibl/alias_table.h). The same code runs in kernels and on the host.
 *
 * Buffers (built by lab::ibl::Environment, ibl/environment.hpp), for face size N:
 *   texels  6 N^2 float4, index (face * N + j) * N + i: xyz the linear RGB radiance, the average
 *           over the texel's solid angle, read with the nearest-texel rule, so the radiance is
 *           constant on every texel; w the probability with which the sampler draws the texel,
 *           computed by the host from the alias tables below, rounding included
 *           (ibl/distribution.hpp), so that environment_pdf() reads the one cache line
 *           environment_radiance() reads for the same direction;
 *   alias   6N + 6N^2 AliasEntry: the alias table over the 6N rows of the faces stacked top to
 *           bottom (row r = face * N + j), then row r's table over its N texels at 6N + r N.
 * A sample reads one entry of the rows' table (24 KB at N = 512: it stays cached), one entry of a
 * row's, and the texel: two lines of memory, each at an address known before the load, which the
 * path tracer asks the cache for ahead (kernels/path_tracer_wavefront.h). A texel's probability is
 * proportional to its luminance times its solid angle, plus a floor so that every texel can be
 * drawn (ibl/distribution.hpp).
 *
 * Rotation: the environment is turned by the angle theta about +y (right-handed), so what the
 * image shows in direction e is seen in world direction R e, with
 *   R (x, y, z) = (cos theta x + sin theta z, y, -sin theta x + cos theta z);
 * theta = 90 degrees brings the image's +x to world -z and its +z to world +x. */
#ifndef IBL_ENVIRONMENT_H
#define IBL_ENVIRONMENT_H

#include "single_source/vocabulary.h"
#include "ibl/cubemap.h"
#include "ibl/alias_table.h"

/* Plain 4-byte scalars only: the same layout in OpenCL C and C++, passed to kernels by value. */
typedef struct EnvironmentMap {
    int face_size;      /* N: every face is N x N texels */
    float rotation_cos; /* cos and sin of the rotation about +y */
    float rotation_sin;
    float intensity;    /* multiplies the texels' radiance: 2^exposure */
} EnvironmentMap;

/* World direction -> direction in the image's frame: R^-1 w. */
SS_FN float3 environment_to_local(const EnvironmentMap* env, float3 w) {
    float c = env->rotation_cos, s = env->rotation_sin;
    return make_float3(c * w.x - s * w.z, w.y, s * w.x + c * w.z);
}

/* Direction in the image's frame -> world direction: R e. */
SS_FN float3 environment_to_world(const EnvironmentMap* env, float3 e) {
    float c = env->rotation_cos, s = env->rotation_sin;
    return make_float3(c * e.x + s * e.z, e.y, -s * e.x + c * e.z);
}

/* The texel world direction `direction` (any length but 0) falls in, and its face coordinates a, b
 * (ibl/cubemap.h): what environment_radiance() and environment_pdf() read. */
SS_FN int environment_texel(const EnvironmentMap* env, float3 direction, float* a, float* b) {
    return cubemap_texel(env->face_size, environment_to_local(env, direction), a, b);
}

/* A texel's radiance: its rgb times the map's intensity. */
SS_FN float3 environment_texel_radiance(const EnvironmentMap* env, float4 texel) {
    return make_float3(texel.x, texel.y, texel.z) * env->intensity;
}

/* Radiance arriving from world direction `direction` (any length but 0): the nearest texel. */
SS_FN float3 environment_radiance(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, float3 direction) {
    float a, b;
    return environment_texel_radiance(env, texels[environment_texel(env, direction, &a, &b)]);
}

/* The same, filtered: bilinear between the four texel centres nearest to the direction on its
 * face (clamped at the face's edges). For what the eye sees directly or through mirrors, where a
 * face of a few hundred texels would show blocks. Nothing but the path itself estimates those
 * rays, so the filter changes no MIS weight; the lighting of rough surfaces keeps
 * environment_radiance, the piecewise-constant function whose pdf the sampler matches. */
SS_FN float3 environment_radiance_filtered(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, float3 direction) {
    int n = env->face_size;
    float a, b;
    int face = cubemap_face(environment_to_local(env, direction), &a, &b);
    /* texel centres sit at integer x, y */
    float x = fmin(fmax((a + 1.0f) * 0.5f * (float)n - 0.5f, 0.0f), (float)(n - 1));
    float y = fmin(fmax((b + 1.0f) * 0.5f * (float)n - 0.5f, 0.0f), (float)(n - 1));
    int i0 = (int)x, j0 = (int)y; /* floor: x, y >= 0 */
    int i1 = min(i0 + 1, n - 1), j1 = min(j0 + 1, n - 1);
    float fx = x - (float)i0, fy = y - (float)j0;
    int row0 = (face * n + j0) * n, row1 = (face * n + j1) * n;
    float4 top = mix(texels[row0 + i0], texels[row0 + i1], fx);
    float4 bottom = mix(texels[row1 + i0], texels[row1 + i1], fx);
    return environment_texel_radiance(env, mix(top, bottom, fy));
}

/* Solid-angle density of a point (a, b) of a texel drawn with probability `probability`, the point
 * uniform in the texel's square of area (2/N)^2 in face coordinates: the area density
 * probability / (2/N)^2 times dA/d(omega) = (1 + a^2 + b^2)^(3/2) (ibl/cubemap.h). */
SS_FN float environment_texel_density(int face_size, float probability, float a, float b) {
    float texel_area = sqr(2.0f / (float)face_size);
    return probability / texel_area * cubemap_area_per_solid_angle(a, b);
}

/* Solid-angle density with which environment_sample() returns world direction `direction`: the
 * probability of its texel, stored in the texel's w (the top of this file), as a density. */
SS_FN float environment_pdf(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, float3 direction) {
    float a, b;
    float probability = texels[environment_texel(env, direction, &a, &b)].w;
    return environment_texel_density(env->face_size, probability, a, b);
}

/* environment_radiance() and environment_pdf() of one direction from one lookup of its texel. */
SS_FN float3 environment_radiance_pdf(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, float3 direction, float* pdf) {
    float a, b;
    float4 t = texels[environment_texel(env, direction, &a, &b)];
    *pdf = environment_texel_density(env->face_size, t.w, a, b);
    return environment_texel_radiance(env, t);
}

/* The rows' alias table and row `row`'s (the top of this file). */
SS_FN GLOBAL_MEM const AliasEntry* environment_row_table(GLOBAL_MEM const AliasEntry* alias) { return alias; }
SS_FN GLOBAL_MEM const AliasEntry* environment_column_table(const EnvironmentMap* env, GLOBAL_MEM const AliasEntry* alias, int row) {
    return alias_grid_column_table(alias, CUBEMAP_FACES * env->face_size, env->face_size, row);
}

/* The cell (row = face * N + j, column) that environment_sample(u1, u2) draws, and the offsets of
 * u1 and u2 inside the parts of [0, 1) that drew it (ibl/alias_table.h). */
SS_FN void environment_sample_cell(const EnvironmentMap* env, GLOBAL_MEM const AliasEntry* alias, float u1, float u2, int* row,
                                   int* column, float* row_offset, float* column_offset) {
    alias_grid_sample(alias, CUBEMAP_FACES * env->face_size, env->face_size, u1, u2, row, column, row_offset, column_offset);
}

/* A world direction drawn with density proportional to the texels' weights: a texel from
 * (u1, u2) through the alias tables, then a uniform point in its square from the offsets of u1 and
 * u2. *pdf: its solid-angle density, environment_pdf() of the returned direction. That is the drawn
 * texel's density except on a texel edge, where rounding in the normalisation and rotation may move
 * the direction into the neighbour: then *pdf is the neighbour's, the texel environment_radiance()
 * reads, so radiance / pdf never mixes two texels. *radiance: environment_radiance() of the
 * direction, from the same lookup. */
SS_FN float3 environment_sample_radiance(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, GLOBAL_MEM const AliasEntry* alias,
                                         float u1, float u2, float* pdf, float3* radiance) {
    int n = env->face_size;
    int row, column;
    float row_offset, column_offset;
    environment_sample_cell(env, alias, u1, u2, &row, &column, &row_offset, &column_offset);
    int face = row / n;
    int j = row - face * n;
    float a = -1.0f + 2.0f * ((float)column + column_offset) / (float)n;
    float b = -1.0f + 2.0f * ((float)j + row_offset) / (float)n;
    float3 direction = environment_to_world(env, normalize(cubemap_face_point(face, a, b)));
    *radiance = environment_radiance_pdf(env, texels, direction, pdf);
    return direction;
}

/* The same without the radiance. */
SS_FN float3 environment_sample(const EnvironmentMap* env, GLOBAL_MEM const float4* texels, GLOBAL_MEM const AliasEntry* alias, float u1,
                                float u2, float* pdf) {
    float3 radiance;
    return environment_sample_radiance(env, texels, alias, u1, u2, pdf, &radiance);
}

/* What environment_sample(u1, u2) reads, found as it finds it, for a caller that asks the cache for
 * it ahead (the path tracer's CPU wavefront, kernels/path_tracer_wavefront.h):
 *  - the entry of the drawn row's table (its index in `alias`), which needs only the rows' table;
 *  - the drawn texel, which needs that entry too. On a texel's edge the sample's direction may fall
 *    in the neighbour, whose texel environment_pdf() then reads. */
SS_FN int environment_sample_column_entry(const EnvironmentMap* env, GLOBAL_MEM const AliasEntry* alias, float u1, float u2) {
    int n = env->face_size;
    float row_offset, f;
    int row = alias_table_sample(environment_row_table(alias), CUBEMAP_FACES * n, u1, &row_offset);
    return (int)(environment_column_table(env, alias, row) - alias) + alias_table_entry(n, u2, &f);
}

SS_FN int environment_sample_texel(const EnvironmentMap* env, GLOBAL_MEM const AliasEntry* alias, float u1, float u2) {
    int row, column;
    float row_offset, column_offset;
    environment_sample_cell(env, alias, u1, u2, &row, &column, &row_offset, &column_offset);
    return row * env->face_size + column; /* row = face * N + j: texel (face * N + j) * N + column */
}

#endif
