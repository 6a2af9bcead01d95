/* One pass of the edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010,
 * "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination Filtering") with the
 * variance-guided luminance weight of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided
 * Filtering", section 4.4), for a pixel: the 5 x 5 B3-spline taps h(i) h(j), i, j in -2..2, spaced
 * `step` pixels apart, each weighted by how alike the two pixels' surfaces are:
 *   w_n = max(0, n_p . n_q)^sigma_normal                                  (normals)
 *   w_z = exp(-|z_p - z_q| / (sigma_depth z_p |p - q| / width + eps))    (depth, relative, per pixel of distance)
 *   w_l = exp(-|l_p - l_q| / (sigma_luminance sqrt(g3x3(var_p)) + eps))   (luminance, in standard deviations)
 * where g3x3 is the variance blurred over the 3 x 3 neighbourhood (SVGF's guard against a variance
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
    float sigma_normal;    /* exponent of the normals' cosine */
    float sigma_depth;     /* tolerated relative depth change across the image's width */
    float sigma_luminance; /* tolerated luminance difference, in standard deviations */
} AtrousPass;

SS_FN AtrousPass atrous_pass(int width, int height, int step, float sigma_normal, float sigma_depth, float sigma_luminance) {
    AtrousPass pass = {width, height, step, sigma_normal, sigma_depth, sigma_luminance};
    return pass;
}

SS_FN float atrous_luminance(float4 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* illumination: per pixel rgb and, in w, the variance of its luminance; guide: per pixel the unit
 * normal (xyz) and the camera ray's depth (w, <= 0 where it hit nothing). */
SS_FN float4 atrous_pixel(const AtrousPass* pass, GLOBAL_MEM const float4* illumination, GLOBAL_MEM const float4* guide, int x, int y) {
    const int w = pass->width, h = pass->height, p = y * w + x;
    const float4 cp = illumination[p], gp = guide[p];
    if (gp.w <= 0.0f) return cp;
    /* the B3 spline [1 4 6 4 1] / 16 from the centre out */
    const float b3[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
    /* the variance blurred over 3 x 3 (a 1-2-1 Gaussian), within the image */
    float var_sum = 0.0f, var_weight = 0.0f;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const int qx = x + i, qy = y + j;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const float g = (i == 0 ? 0.5f : 0.25f) * (j == 0 ? 0.5f : 0.25f);
            var_sum += g * illumination[qy * w + qx].w;
            var_weight += g;
        }
    const float lp = atrous_luminance(cp);
    const float luminance_scale = pass->sigma_luminance * sqrt(fmax(var_sum / var_weight, 0.0f)) + 1e-10f;
    float sum_w = 0.0f, sum_var = 0.0f;
    float3 sum_c = make_float3(0.0f, 0.0f, 0.0f);
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
            const int qx = x + i * pass->step, qy = y + j * pass->step;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const float4 cq = illumination[qy * w + qx], gq = guide[qy * w + qx];
            if (gq.w <= 0.0f) continue;
            const float hw = b3[i < 0 ? -i : i] * b3[j < 0 ? -j : j];
            const float w_n = pow(fmax(0.0f, gp.x * gq.x + gp.y * gq.y + gp.z * gq.z), pass->sigma_normal);
            const float distance = sqrt((float)(i * i + j * j)) * (float)pass->step;
            const float w_z = exp(-fabs(gp.w - gq.w) / (pass->sigma_depth * gp.w * distance / (float)w + 1e-10f));
            const float w_l = exp(-fabs(lp - atrous_luminance(cq)) / luminance_scale);
            const float weight = hw * w_n * w_z * w_l;
            sum_w += weight;
            sum_c += weight * make_float3(cq.x, cq.y, cq.z);
            sum_var += weight * weight * cq.w;
        }
    /* the pixel itself always weighs h(0)^2 > 0 */
    return make_float4(sum_c.x / sum_w, sum_c.y / sum_w, sum_c.z / sum_w, sum_var / (sum_w * sum_w));
}

#endif
