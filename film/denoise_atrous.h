/* One pass of the edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010,
 * "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination Filtering") with the
 * variance-guided luminance weight of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided
 * Filtering", section 4.4), for a pixel: the 5 x 5 B3-spline taps h(i) h(j), i, j in -2..2, spaced
 * `step` pixels apart, each weighted by how alike the two pixels' surfaces are:
 *   w_n = exp(-sigma_normal (1 - n_p . n_q)), 0 for n_p . n_q <= 0          (normals)
 *   w_z = exp(-|z_p - z_q| / (sigma_depth z_p |p - q| / width + eps))    (depth, relative, per pixel of distance)
 *   w_l = exp(-|l_p - l_q| / (sigma_luminance sqrt(g3x3(var_p)) + eps))   (luminance, in standard deviations)
 * The normal weight is SVGF's max(0, n_p . n_q)^sigma_normal to first order in 1 - n_p . n_q (ln c
 * ~ c - 1) and as steep, and it joins the other two in one exponential per tap: the pass is a few
 * multiply-adds, two loads and one exp a tap, without a branch, so that it runs on vector lanes.
 * g3x3 is the variance blurred over the 3 x 3 neighbourhood (SVGF's guard against a variance
 * estimate of few samples). The filtered value is sum(h w c) / sum(h w) and its variance
 * sum((h w)^2 var) / sum(h w)^2, which the next, wider pass reads.
 * What it filters is the illumination (radiance / albedo: film/denoise.cpp), so texture is not
 * blurred. A pixel without a surface (depth <= 0: the background) is left as it is and never
 * mixed with one that has a surface.
 * Written in the common subset of OpenCL C and C++17 (docs/architecture.md). */
#ifndef FILM_DENOISE_ATROUS_H
#define FILM_DENOISE_ATROUS_H

#include "single_source/vocabulary.h"

typedef struct {
    int width, height;
    int step;              /* 1, 2, 4, ...: this pass's tap spacing */
    float sigma_normal;    /* how fast the weight falls as the normals part: exp(-sigma_normal (1 - cos)) */
    float sigma_depth;     /* tolerated relative depth change across the image's width */
    float sigma_luminance; /* tolerated luminance difference, in standard deviations */
} AtrousPass;

SS_FN AtrousPass atrous_pass(int width, int height, int step, float sigma_normal, float sigma_depth, float sigma_luminance) {
    AtrousPass pass = {width, height, step, sigma_normal, sigma_depth, sigma_luminance};
    return pass;
}

SS_FN SDF_FLOAT atrous_luminance(SDF_FLOAT r, SDF_FLOAT g, SDF_FLOAT b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

/* A pixel index clamped into the image: taps past the border read the edge pixel with weight 0,
 * so every work-item takes the same path. */
SS_FN int atrous_index(int x, int y, int width, int height) {
    const int cx = x < 0 ? 0 : (x >= width ? width - 1 : x);
    const int cy = y < 0 ? 0 : (y >= height ? height - 1 : y);
    return cy * width + cx;
}


/* The pass computes in SDF_FLOAT (single_source/vocabulary.h): one pixel on the host, or with
 * SDF_LANES = 8 (kernels/denoise.cl) eight consecutive pixels of a row at once, each value a float8
 * of the eight, so that the device's pass runs on the CPU's vector lanes whatever PoCL's work-item
 * vectoriser makes of it (docs/render.md, "Cost"). A lane's arithmetic is the pixel's, in the same
 * order. SDF_MASK holds the lanes' integers (their x). */
#if defined(SDF_LANES)
#define ATROUS_LANE_X(x) ((int8)(x) + (int8)(0, 1, 2, 3, 4, 5, 6, 7))
#else
#define ATROUS_LANE_X(x) (x)
#endif

/* the lanes' taps inside the image: 1, or 0 past a border (where the clamped load reads the edge) */
SS_FN SDF_FLOAT atrous_inside_lanes(SDF_MASK x, int y, int width, int height) {
    return select((SDF_FLOAT)0.0f, (SDF_FLOAT)1.0f, (SDF_MASK)((x >= 0) & (x < width))) * ((y >= 0 && y < height) ? 1.0f : 0.0f);
}

/* One pixel's four floats, or the lanes' (v[c]: channel c of every lane). */
typedef struct {
    SDF_FLOAT v[4];
} AtrousTexel;

/* The four floats of the pixel (x, y), clamped into the image, from a buffer of four floats a pixel;
 * on eight lanes, those of the pixels x .. x + 7 of row y: four 8-float loads shuffled apart where
 * the eight are inside the row, a pixel at a time at its ends. */
SS_FN AtrousTexel atrous_load(GLOBAL_MEM const float* buffer, int x, int y, int width, int height) {
    AtrousTexel t;
#if defined(SDF_LANES)
    if (x >= 0 && x + 7 < width) {
        const int cy = y < 0 ? 0 : (y >= height ? height - 1 : y);
        GLOBAL_MEM const float* row = buffer + 4 * (cy * width + x);
        /* four 8-float loads (two pixels each; a 16-float one would change the CPU's calling
         * convention without AVX-512) */
        const float8 a = vload8(0, row), b = vload8(1, row), c = vload8(2, row), d = vload8(3, row);
        t.v[0] = (float8)(a.s04, b.s04, c.s04, d.s04);
        t.v[1] = (float8)(a.s15, b.s15, c.s15, d.s15);
        t.v[2] = (float8)(a.s26, b.s26, c.s26, d.s26);
        t.v[3] = (float8)(a.s37, b.s37, c.s37, d.s37);
    } else {
        float lanes[4][8];
        for (int l = 0; l < 8; ++l) {
            const int q = 4 * atrous_index(x + l, y, width, height);
            for (int c = 0; c < 4; ++c) lanes[c][l] = buffer[q + c];
        }
        for (int c = 0; c < 4; ++c) t.v[c] = vload8(0, lanes[c]);
    }
#else
    const int q = 4 * atrous_index(x, y, width, height);
    for (int c = 0; c < 4; ++c) t.v[c] = buffer[q + c];
#endif
    return t;
}

/* illumination: per pixel four floats, rgb and the variance of its luminance; guide: per pixel four
 * floats, the unit normal and the camera ray's depth (<= 0 where it hit nothing). The pixel (x, y)'s
 * (or the lanes' x .. x + 7) filtered four floats go to out[0..3]. */
SS_FN void atrous_pixel(const AtrousPass* pass, GLOBAL_MEM const float* illumination, GLOBAL_MEM const float* guide, int x, int y, SDF_FLOAT* out) {
    const int w = pass->width, h = pass->height;
    const SDF_MASK lane_x = ATROUS_LANE_X(x);
    const AtrousTexel own = atrous_load(illumination, x, y, w, h), own_guide = atrous_load(guide, x, y, w, h);
    const SDF_FLOAT nx = own_guide.v[0], ny = own_guide.v[1], nz = own_guide.v[2], zp = own_guide.v[3];
    /* the B3 spline [1 4 6 4 1] / 16 from the centre out */
    const float b3[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
    /* the variance blurred over 3 x 3 (a 1-2-1 Gaussian), within the image */
    SDF_FLOAT var_sum = 0.0f, var_weight = 0.0f;
    SS_PRAGMA_UNROLL
    for (int j = -1; j <= 1; ++j)
        SS_PRAGMA_UNROLL
        for (int i = -1; i <= 1; ++i) {
            const SDF_FLOAT g = (i == 0 ? 0.5f : 0.25f) * (j == 0 ? 0.5f : 0.25f) * atrous_inside_lanes(lane_x + i, y + j, w, h);
            var_sum += g * atrous_load(illumination, x + i, y + j, w, h).v[3];
            var_weight += g;
        }
    const SDF_FLOAT lp = atrous_luminance(own.v[0], own.v[1], own.v[2]);
    const SDF_FLOAT inv_luminance_scale = 1.0f / (pass->sigma_luminance * sqrt(fmax(var_sum / var_weight, 0.0f)) + 1e-10f);
    /* 1 / (sigma_depth z_p |p - q| / width) = inv_depth_scale / sqrt(i^2 + j^2) */
    const SDF_FLOAT inv_depth_scale = (float)w / (pass->sigma_depth * fmax(zp, 1e-10f) * (float)pass->step);
    const float inv_root[9] = {0.0f, 1.0f, 0.70710678f, 0.57735027f, 0.5f, 0.44721360f, 0.40824829f, 0.37796447f, 0.35355339f};
    SDF_FLOAT sum_w = 0.0f, sum_r = 0.0f, sum_g = 0.0f, sum_b = 0.0f, sum_var = 0.0f;
    SS_PRAGMA_UNROLL
    for (int j = -2; j <= 2; ++j)
        SS_PRAGMA_UNROLL
        for (int i = -2; i <= 2; ++i) {
            const int qx = x + i * pass->step, qy = y + j * pass->step;
            const AtrousTexel c = atrous_load(illumination, qx, qy, w, h), g = atrous_load(guide, qx, qy, w, h);
            const SDF_FLOAT cosine = nx * g.v[0] + ny * g.v[1] + nz * g.v[2], zq = g.v[3];
            const SDF_FLOAT exponent = -pass->sigma_normal * (1.0f - cosine) - fabs(zp - zq) * inv_depth_scale * inv_root[i * i + j * j] -
                                       fabs(lp - atrous_luminance(c.v[0], c.v[1], c.v[2])) * inv_luminance_scale;
            /* the pixel itself weighs h(0)^2 whatever its guide (a mean normal can be 0); another
             * counts only inside the image, on a surface, facing the same side */
            const bool centre = i == 0 && j == 0;
            const SDF_MASK counts = (SDF_MASK)((zq > 0.0f) & (cosine > 0.0f));
            const SDF_FLOAT edge = centre ? (SDF_FLOAT)1.0f : select((SDF_FLOAT)0.0f, exp(exponent), counts);
            const SDF_FLOAT weight = b3[i < 0 ? -i : i] * b3[j < 0 ? -j : j] * atrous_inside_lanes(lane_x + i * pass->step, qy, w, h) * edge;
            sum_w += weight;
            sum_r += weight * c.v[0];
            sum_g += weight * c.v[1];
            sum_b += weight * c.v[2];
            sum_var += weight * weight * c.v[3];
        }
    /* a pixel without a surface is left as it is */
    const SDF_MASK surface = (SDF_MASK)(zp > 0.0f);
    out[0] = select(own.v[0], sum_r / sum_w, surface);
    out[1] = select(own.v[1], sum_g / sum_w, surface);
    out[2] = select(own.v[2], sum_b / sum_w, surface);
    out[3] = select(own.v[3], sum_var / (sum_w * sum_w), surface);
}

#endif
