/* The display denoiser's a-trous pass (film/denoise_atrous.h) on the render device: one work-item
 * per pixel, the pass's values as scalars. The host runs the same function (film/denoise.cpp). */

/* No fused multiply-add, as the host build (x86-64 baseline) rounds every product. */
#pragma OPENCL FP_CONTRACT OFF

#include "film/denoise_atrous.h"

__kernel void denoise_atrous_pass(int width, int height, int step, float sigma_normal, float sigma_depth, float sigma_luminance,
                                  __global const float* illumination, __global const float* guide, __global float* out) {
    /* no early return for the work-items past the image (the launch rounds up to the local size):
     * they compute the last pixel and do not store it, so the work-group's loop has one exit and
     * PoCL can run its work-items as vector lanes */
    const int n = width * height;
    const int i = (int)get_global_id(0);
    const int p = i < n ? i : n - 1;
    const AtrousPass pass = atrous_pass(width, height, step, sigma_normal, sigma_depth, sigma_luminance);
    float filtered[4];
    atrous_pixel(&pass, illumination, guide, p % width, p / width, filtered);
    if (i < n)
        for (int c = 0; c < 4; ++c) out[4 * i + c] = filtered[c];
}
