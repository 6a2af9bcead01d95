/* The display denoiser's a-trous pass (film/denoise_atrous.h) on the render device: one work-item
 * per eight consecutive pixels of a row, each value a float8 of the eight (SDF_LANES), so that the
 * pass runs on the CPU's vector lanes without PoCL's work-item vectoriser (docs/render.md, "Cost");
 * the host builds it with -DSDF_LANES=8 (kernels/host/denoise_device.cpp).
 * The host runs the same function a pixel at a time (film/denoise.cpp). */

/* Multiply-adds fused: a pass about 10 % faster; the host build (x86-64 baseline) rounds every
 * product, and the two differ by under 1e-6 after the passes (tests/test_denoise_opencl.cpp). */
#pragma OPENCL FP_CONTRACT ON

#include "film/denoise_atrous.h"

/* work-item i: row i / packets, pixels 8 (i % packets) .. + 7 of it, packets = ceil(width / 8);
 * the lanes past the row's end compute its last pixel and are not stored */
__kernel void denoise_atrous_pass(int width, int height, int step, float sigma_normal, float sigma_depth, float sigma_luminance,
                                  __global const float* illumination, __global const float* guide, __global float* out) {
    const int packets = (width + 7) / 8;
    const int i = (int)get_global_id(0);
    if (i >= packets * height) return;
    const int y = i / packets, x = 8 * (i % packets);
    const AtrousPass pass = atrous_pass(width, height, step, sigma_normal, sigma_depth, sigma_luminance);
    float8 filtered[4];
    atrous_pixel(&pass, illumination, guide, x, y, filtered);
    __global float* row = out + 4 * (y * width + x);
    if (x + 7 < width) {
        /* interleaved back into four floats a pixel, two pixels a store */
        const float8 r = filtered[0], g = filtered[1], b = filtered[2], v = filtered[3];
        vstore8((float8)(r.s0, g.s0, b.s0, v.s0, r.s1, g.s1, b.s1, v.s1), 0, row);
        vstore8((float8)(r.s2, g.s2, b.s2, v.s2, r.s3, g.s3, b.s3, v.s3), 1, row);
        vstore8((float8)(r.s4, g.s4, b.s4, v.s4, r.s5, g.s5, b.s5, v.s5), 2, row);
        vstore8((float8)(r.s6, g.s6, b.s6, v.s6, r.s7, g.s7, b.s7, v.s7), 3, row);
    } else {
        float lanes[4][8];
        for (int c = 0; c < 4; ++c) vstore8(filtered[c], 0, lanes[c]);
        for (int l = 0; x + l < width; ++l)
            for (int c = 0; c < 4; ++c) row[4 * l + c] = lanes[c][l];
    }
}
