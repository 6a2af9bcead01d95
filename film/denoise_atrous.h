/* One pass of the edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010,
 * "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination Filtering") with the
 * variance-guided luminance weight of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided
 * Filtering", section 4.4), for a pixel: the 3 x 3 taps h(i) h(j) of the linear spline
 * h = [1 2 1] / 4, i, j in -1..1, spaced `step` pixels apart, each weighted by how alike the two
 * pixels' surfaces are:
 *   w_n = exp(-sigma_normal (1 - n_p . n_q)), 0 for n_p . n_q <= 0          (normals)
 *   w_z = exp(-|z_p - z_q| / (sigma_depth z_p |p - q| / width + eps))    (depth, relative, per pixel of distance)
 *   w_l = exp(-|l_p - l_q| / (sigma_luminance sqrt(g3x3(var_p)) + eps))   (luminance, in standard deviations)
 * The normal weight is SVGF's max(0, n_p . n_q)^sigma_normal to first order in 1 - n_p . n_q (ln c
 * ~ c - 1) and as steep, and it joins the other two in one exponential per tap: the pass is a few
 * multiply-adds, two loads and one exp a tap, without a branch, so that it runs on vector lanes.
 * g3x3 is the variance blurred by the same 3 x 3 taps (SVGF's guard against a variance estimate of
 * few samples; SVGF blurs over the adjacent pixels, the same as the first pass's taps). The 3 x 3
 * taps instead of Dammertz's and SVGF's 5 x 5 B3 spline: a third of the loads and weights a pass, and
 * at the viewer's size no more error (docs/render.md, "Measured"). The filtered value is
 * sum(h w c) / sum(h w) and its variance sum((h w)^2 var) / sum(h w)^2, which the next, wider pass
 * reads.
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

/* e^-x for x >= 0 (and a little below), to a relative 5e-5: 2^-y with y = x log2(e) split into a
 * whole n and a rest r in [-1/2, 1/2], e^(-r ln 2) by its Taylor series to the fourth power, 2^-n from
 * the exponent's bits. A weight under 2^-125 is 0 to the filter, so y stops there. Cheaper than the
 * library's exp on eight lanes (no table, no special cases), and one formula on the host and the
 * device. */
#if defined(__OPENCL_C_VERSION__) && defined(SDF_LANES)
SS_FN float8 atrous_pow2_neg(float8 n) { return as_float8((int8)(127 - convert_int8(n)) << 23); }
#elif defined(__OPENCL_C_VERSION__)
SS_FN float atrous_pow2_neg(float n) { return as_float((127 - (int)n) << 23); }
#else
SS_FN float atrous_pow2_neg(float n) { return ldexp(1.0f, -(int)n); }
#endif
SS_FN SDF_FLOAT atrous_exp_neg(SDF_FLOAT x) {
    const SDF_FLOAT y = fmin(x * 1.44269504f, 125.0f);
    const SDF_FLOAT n = floor(y + 0.5f);
    const SDF_FLOAT f = (n - y) * 0.69314718f;
    const SDF_FLOAT series = 1.0f + f * (1.0f + f * (0.5f + f * (1.0f / 6.0f + f * (1.0f / 24.0f))));
    return series * atrous_pow2_neg(n);
}

/* One pixel's four floats, or the lanes' (v[c]: channel c of every lane). */
typedef struct {
    SDF_FLOAT v[4];
} AtrousTexel;

/* The four floats of the pixel (x, y), clamped into the image, from a buffer of four floats a pixel;
 * on eight lanes, those of the pixels x .. x + 7 of row y: four 8-float loads shuffled apart where
 * the eight are inside the row, a pixel at a time at its ends. */
SS_FN SS_INLINE_ALWAYS AtrousTexel atrous_load(GLOBAL_MEM const float* buffer, int x, int y, int width, int height) {
    AtrousTexel t;
#if defined(SDF_LANES)
    if (x >= 0 && x + 7 < width) {
        const int cy = y < 0 ? 0 : (y >= height ? height - 1 : y);
        GLOBAL_MEM const float* row = buffer + 4 * (cy * width + x);
        /* four 8-float loads (two pixels each; a 16-float one would change the CPU's calling
         * convention without AVX-512) */
        const float8 a = vload8(0, row), b = vload8(1, row), c = vload8(2, row), d = vload8(3, row);
        /* a 4 x 8 transpose in two rounds of two-source shuffles (one instruction each on AVX-512);
         * the swizzle form (float8)(a.s04, b.s04, c.s04, d.s04) was compiled into two-float loads
         * and inserts, and the passes took 1.4 times as long */
        const float8 ab_rg = __builtin_shufflevector(a, b, 0, 4, 8, 12, 1, 5, 9, 13), ab_bv = __builtin_shufflevector(a, b, 2, 6, 10, 14, 3, 7, 11, 15);
        const float8 cd_rg = __builtin_shufflevector(c, d, 0, 4, 8, 12, 1, 5, 9, 13), cd_bv = __builtin_shufflevector(c, d, 2, 6, 10, 14, 3, 7, 11, 15);
        t.v[0] = __builtin_shufflevector(ab_rg, cd_rg, 0, 1, 2, 3, 8, 9, 10, 11);
        t.v[1] = __builtin_shufflevector(ab_rg, cd_rg, 4, 5, 6, 7, 12, 13, 14, 15);
        t.v[2] = __builtin_shufflevector(ab_bv, cd_bv, 0, 1, 2, 3, 8, 9, 10, 11);
        t.v[3] = __builtin_shufflevector(ab_bv, cd_bv, 4, 5, 6, 7, 12, 13, 14, 15);
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
    /* the 3 x 3 taps, row by row; [4] is the pixel itself */
    AtrousTexel c[9], g[9];
    SDF_FLOAT tap[9];
    SDF_FLOAT var_sum = 0.0f, var_weight = 0.0f;
    SS_PRAGMA_UNROLL
    for (int j = -1; j <= 1; ++j)
        SS_PRAGMA_UNROLL
        for (int i = -1; i <= 1; ++i) {
            const int k = 3 * (j + 1) + (i + 1);
            const int qx = x + i * pass->step, qy = y + j * pass->step;
            c[k] = atrous_load(illumination, qx, qy, w, h);
            g[k] = atrous_load(guide, qx, qy, w, h);
            /* the 1-2-1 spline's weight, 0 past a border */
            tap[k] = (i == 0 ? 0.5f : 0.25f) * (j == 0 ? 0.5f : 0.25f) * atrous_inside_lanes(lane_x + i * pass->step, qy, w, h);
            var_sum += tap[k] * c[k].v[3];
            var_weight += tap[k];
        }
    const SDF_FLOAT nx = g[4].v[0], ny = g[4].v[1], nz = g[4].v[2], zp = g[4].v[3];
    const SDF_FLOAT lp = atrous_luminance(c[4].v[0], c[4].v[1], c[4].v[2]);
    const SDF_FLOAT inv_luminance_scale = 1.0f / (pass->sigma_luminance * sqrt(fmax(var_sum / var_weight, 0.0f)) + 1e-10f);
    /* 1 / (sigma_depth z_p |p - q| / width), |p - q| = step along an axis, sqrt(2) step diagonally */
    const SDF_FLOAT inv_depth_axis = (float)w / (pass->sigma_depth * fmax(zp, 1e-10f) * (float)pass->step);
    const SDF_FLOAT inv_depth_diagonal = inv_depth_axis * 0.70710678f;
    SDF_FLOAT sum_w = 0.0f, sum_r = 0.0f, sum_g = 0.0f, sum_b = 0.0f, sum_var = 0.0f;
    SS_PRAGMA_UNROLL
    for (int k = 0; k < 9; ++k) {
        const SDF_FLOAT cosine = nx * g[k].v[0] + ny * g[k].v[1] + nz * g[k].v[2], zq = g[k].v[3];
        const SDF_FLOAT penalty = pass->sigma_normal * (1.0f - cosine) + fabs(zp - zq) * (k % 2 == 0 ? inv_depth_diagonal : inv_depth_axis) +
                                  fabs(lp - atrous_luminance(c[k].v[0], c[k].v[1], c[k].v[2])) * inv_luminance_scale;
        const SDF_MASK counts = (SDF_MASK)((zq > 0.0f) & (cosine > 0.0f));
        const SDF_FLOAT edge = k == 4 ? (SDF_FLOAT)1.0f : select((SDF_FLOAT)0.0f, atrous_exp_neg(penalty), counts);
        const SDF_FLOAT weight = tap[k] * edge;
        sum_w += weight;
        sum_r += weight * c[k].v[0];
        sum_g += weight * c[k].v[1];
        sum_b += weight * c[k].v[2];
        sum_var += weight * weight * c[k].v[3];
    }
    const SDF_MASK surface = (SDF_MASK)(zp > 0.0f);
    out[0] = select(c[4].v[0], sum_r / sum_w, surface);
    out[1] = select(c[4].v[1], sum_g / sum_w, surface);
    out[2] = select(c[4].v[2], sum_b / sum_w, surface);
    out[3] = select(c[4].v[3], sum_var / (sum_w * sum_w), surface);
}

#endif
