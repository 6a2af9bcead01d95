/* Rect and disk emitters that show an image (docs/lights.md, "Image emitters"): the radiance on the
 * emitting side at the light's point of coordinates st in [0, 1]^2 (area_light_point) is the texel
 * st falls in, times the light's `emission` as an RGB scale. The image's W columns run along s (U),
 * its H rows along t (V), so that seen from the emitting side, with U to the right and V up, it is
 * the picture as stored, unmirrored: the file's first row lies along the edge t = 1, at +V/2.
 *
 * Buffers (built by the host, render/emitter_images.hpp), after the environment's own:
 *   alias   at l->image a header of EMITTER_IMAGE_HEADER entries, whose `alias` fields hold W, H and
 *           the offset of the first texel in the texels buffer; after it the two-level alias tables
 *           over H rows of W texels (ibl/alias_table.h's alias_grid_sample), each texel weighted by
 *           its luminance times its area, the same for every texel: a rect's texels are equal
 *           parallelograms, a disk's the images of equal squares under the area-keeping
 *           concentric map;
 *   texels  H W float4, row r (t in [r/H, (r+1)/H]) at r W: xyz the linear RGB texel, w the
 *           probability with which those tables draw the texel (rounding included,
 *           ibl/distribution.hpp), so the density of a point is read from the one texel its
 *           radiance is.
 * A point is drawn by area: a texel from the tables, then a uniform point in it, density
 * p_texel W H / A per unit area. Against a constant rect's spherical-rectangle sampler this gives up
 * the cosine and distance of the solid angle for the image's contrast, which a screen or a
 * textured soft box has much more of. */
#ifndef KERNELS_LIGHTS_IMAGE_EMITTER_H
#define KERNELS_LIGHTS_IMAGE_EMITTER_H
#include "single_source/vocabulary.h"
#include "ibl/alias_table.h"
#include "kernels/lights/area_light.h"
#include "kernels/lights/environment_light.h"
#include "kernels/lights/light.h"

#define EMITTER_IMAGE_HEADER 3

typedef struct EmitterImage {
    int width, height;                 /* W, H */
    int texels;                        /* the offset of its first texel */
    GLOBAL_MEM const AliasEntry* alias; /* its tables: H entries over the rows, then H tables of W */
} EmitterImage;

SS_FN EmitterImage emitter_image(const Light* l, EnvironmentBuffers b) {
    GLOBAL_MEM const AliasEntry* header = b.alias + l->image;
    EmitterImage im;
    im.width = header[0].alias;
    im.height = header[1].alias;
    im.texels = header[2].alias;
    im.alias = header + EMITTER_IMAGE_HEADER;
    return im;
}

/* The coordinates st in [0, 1]^2 of the light's point q (the inverse of area_light_point). */
SS_FN float2 area_light_st(const Light* l, float3 q) {
    float2 xy = area_light_coordinates(l, q);
    if (l->type == LIGHT_DISK) return concentric_disk_to_square(xy.x, xy.y);
    return make_float2(clamp(xy.x + 0.5f, 0.0f, 1.0f), clamp(xy.y + 0.5f, 0.0f, 1.0f));
}

/* The texel of the light's point q: its radiance (times the light's scale), and in *pdf_area the
 * density per unit area with which image_emitter_sample_point draws q. */
SS_FN float3 image_emitter_radiance_area_pdf(const Light* l, EnvironmentBuffers b, float3 q, float* pdf_area) {
    EmitterImage im = emitter_image(l, b);
    float2 st = area_light_st(l, q);
    int column = min((int)(st.x * (float)im.width), im.width - 1);
    int row = min((int)(st.y * (float)im.height), im.height - 1);
    float4 texel = b.texels[im.texels + row * im.width + column];
    *pdf_area = texel.w * ((float)im.width * (float)im.height / area_light_area(l));
    return make_float3(texel.x, texel.y, texel.z) * float3_from_array(l->emission);
}

/* A point of the light drawn by its texels' weights (the top of this file), uniform in its texel. */
SS_FN float3 image_emitter_sample_point(const Light* l, EnvironmentBuffers b, float2 u) {
    EmitterImage im = emitter_image(l, b);
    int row, column;
    float row_offset, column_offset;
    alias_grid_sample(im.alias, im.height, im.width, u.x, u.y, &row, &column, &row_offset, &column_offset);
    float2 st = make_float2(((float)column + column_offset) / (float)im.width, ((float)row + row_offset) / (float)im.height);
    return area_light_point(l, st);
}

/* A sample of the light seen from p: its pdf and radiance are read from the texel of the point
 * drawn (the one image_emitter_pdf finds again for its direction). */
SS_FN LightSample image_emitter_sample(const Light* l, EnvironmentBuffers b, float3 p, float2 u) {
    float3 n = area_light_normal(l);
    if (!(dot(p - area_light_center(l), n) > 0.0f)) return light_sample_none(); /* behind it: it emits nothing here */
    float3 q = image_emitter_sample_point(l, b, u);
    LightSample s = light_sample_none();
    float cos_l, pdf_area;
    if (!area_light_sample_point(p, q, n, &s, &cos_l)) return light_sample_none();
    s.radiance = image_emitter_radiance_area_pdf(l, b, q, &pdf_area);
    s.pdf = pdf_area * s.distance * s.distance / cos_l;
    return s;
}

/* The solid-angle density with which image_emitter_sample() from p returns the unit direction wi;
 * 0 when the ray misses the light or meets its back. */
SS_FN float image_emitter_pdf(const Light* l, EnvironmentBuffers b, float3 p, float3 wi) {
    float t, cos_l;
    if (!area_light_ray_hit(l, p, wi, &t, &cos_l)) return 0.0f;
    float pdf_area;
    image_emitter_radiance_area_pdf(l, b, p + wi * t, &pdf_area);
    return pdf_area * t * t / cos_l;
}

/* The density per unit area of image_emitter_sample_point at the light's point q. */
SS_FN float image_emitter_area_pdf(const Light* l, EnvironmentBuffers b, float3 q) {
    float pdf_area;
    image_emitter_radiance_area_pdf(l, b, q, &pdf_area);
    return pdf_area;
}

/* The radiance the light sends from its point q along the unit direction w: its texel's on the
 * emitting side, 0 behind it. */
SS_FN float3 image_emitter_radiance(const Light* l, EnvironmentBuffers b, float3 q, float3 w) {
    if (!(dot(area_light_normal(l), w) > 0.0f)) return float3_splat(0.0f);
    float pdf_area;
    return image_emitter_radiance_area_pdf(l, b, q, &pdf_area);
}

#endif
