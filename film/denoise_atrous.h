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
 * multiply-adds, two loads and one exp a tap, without a branch, so that the work-items of a
 * work-group run as vector lanes.
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

SS_FN float atrous_luminance(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

/* A pixel index clamped into the image: taps past the border read the edge pixel with weight 0,
 * so every work-item takes the same path. */
SS_FN int atrous_index(int x, int y, int width, int height) {
    const int cx = x < 0 ? 0 : (x >= width ? width - 1 : x);
    const int cy = y < 0 ? 0 : (y >= height ? height - 1 : y);
    return cy * width + cx;
}

SS_FN float atrous_inside(int x, int y, int width, int height) { return (x >= 0 && y >= 0 && x < width && y < height) ? 1.0f : 0.0f; }

/* illumination: per pixel four floats, rgb and the variance of its luminance; guide: per pixel four
 * floats, the unit normal and the camera ray's depth (<= 0 where it hit nothing). Both are read as
 * scalars and the result written to out[0..3], never as vector types: a loop that holds a vector
 * type is one LLVM cannot vectorise, and PoCL vectorises the work-group's loop over its items. */
SS_FN void atrous_pixel(const AtrousPass* pass, GLOBAL_MEM const float* illumination, GLOBAL_MEM const float* guide, int x, int y, float* out) {
    const int w = pass->width, h = pass->height, p = 4 * (y * w + x);
    const float nx = guide[p], ny = guide[p + 1], nz = guide[p + 2], zp = guide[p + 3];
    /* the B3 spline [1 4 6 4 1] / 16 from the centre out */
    const float b3[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
    /* the variance blurred over 3 x 3 (a 1-2-1 Gaussian), within the image */
    float var_sum = 0.0f, var_weight = 0.0f;
    SS_PRAGMA_UNROLL
    for (int j = -1; j <= 1; ++j)
        SS_PRAGMA_UNROLL
        for (int i = -1; i <= 1; ++i) {
            const float g = (i == 0 ? 0.5f : 0.25f) * (j == 0 ? 0.5f : 0.25f) * atrous_inside(x + i, y + j, w, h);
            var_sum += g * illumination[4 * atrous_index(x + i, y + j, w, h) + 3];
            var_weight += g;
        }
    const float lp = atrous_luminance(illumination[p], illumination[p + 1], illumination[p + 2]);
    const float inv_luminance_scale = 1.0f / (pass->sigma_luminance * sqrt(fmax(var_sum / var_weight, 0.0f)) + 1e-10f);
    /* 1 / (sigma_depth z_p |p - q| / width) = inv_depth_scale / sqrt(i^2 + j^2) */
    const float inv_depth_scale = (float)w / (pass->sigma_depth * fmax(zp, 1e-10f) * (float)pass->step);
    const float inv_root[9] = {0.0f, 1.0f, 0.70710678f, 0.57735027f, 0.5f, 0.44721360f, 0.40824829f, 0.37796447f, 0.35355339f};
    float sum_w = 0.0f, sum_r = 0.0f, sum_g = 0.0f, sum_b = 0.0f, sum_var = 0.0f;
    /* unrolled, so that the work-group's loop over its work-items is the only loop left to vectorise */
    SS_PRAGMA_UNROLL
    for (int j = -2; j <= 2; ++j)
        SS_PRAGMA_UNROLL
        for (int i = -2; i <= 2; ++i) {
            const int qx = x + i * pass->step, qy = y + j * pass->step;
            const int q = 4 * atrous_index(qx, qy, w, h);
            const float r = illumination[q], g = illumination[q + 1], b = illumination[q + 2], var = illumination[q + 3];
            const float cosine = nx * guide[q] + ny * guide[q + 1] + nz * guide[q + 2], zq = guide[q + 3];
            const float exponent = -pass->sigma_normal * (1.0f - cosine) - fabs(zp - zq) * inv_depth_scale * inv_root[i * i + j * j] -
                                   fabs(lp - atrous_luminance(r, g, b)) * inv_luminance_scale;
            /* the pixel itself weighs h(0)^2 whatever its guide (a mean normal can be 0); another
             * counts only inside the image, on a surface, facing the same side */
            const bool centre = i == 0 && j == 0;
            const bool counts = zq > 0.0f && cosine > 0.0f;
            const float edge = centre ? 1.0f : (counts ? exp(exponent) : 0.0f);
            const float weight = b3[i < 0 ? -i : i] * b3[j < 0 ? -j : j] * atrous_inside(qx, qy, w, h) * edge;
            sum_w += weight;
            sum_r += weight * r;
            sum_g += weight * g;
            sum_b += weight * b;
            sum_var += weight * weight * var;
        }
    /* a pixel without a surface is left as it is */
    const bool surface = zp > 0.0f;
    out[0] = surface ? sum_r / sum_w : illumination[p];
    out[1] = surface ? sum_g / sum_w : illumination[p + 1];
    out[2] = surface ? sum_b / sum_w : illumination[p + 2];
    out[3] = surface ? sum_var / (sum_w * sum_w) : illumination[p + 3];
}

#endif
