/* The display denoiser's a-trous pass (film/denoise_atrous.h) on the render device: one work-item
 * per pixel, the pass's values as scalars. The host runs the same function (film/denoise.cpp). */

/* No fused multiply-add, as the host build (x86-64 baseline) rounds every product. */
#pragma OPENCL FP_CONTRACT OFF

#include "film/denoise_atrous.h"

__kernel void denoise_atrous_pass(int width, int height, int step, float sigma_normal, float sigma_depth, float sigma_luminance,
                                  __global const float4* illumination, __global const float4* guide, __global float4* out) {
    int i = (int)get_global_id(0);
    if (i >= width * height) return;
    const AtrousPass pass = atrous_pass(width, height, step, sigma_normal, sigma_depth, sigma_luminance);
    out[i] = atrous_pixel(&pass, illumination, guide, i % width, i / width);
}
