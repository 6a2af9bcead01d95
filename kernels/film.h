/* The film every integrator writes into. Per pixel:
 *   accumulation  float4: xyz the sum of the finite samples the pixel's own work-item traced, w the
 *                 count of its non-finite ones (left out of the mean, reported, never hidden);
 *   squares       float4: xyz the sum of the squares of the same finite samples (w unused), for
 *                 the variance of the pixel's mean (render/film_resolve.cpp): sums merge and resume
 *                 by adding, as the sum does;
 *   splat         3 floats (stored as their bits in uints): contributions other work-items add to
 *                 this pixel -- light tracing (t = 1) lands anywhere on the film.
 * The pixel's estimate is accumulation.xyz / (samples - accumulation.w) + splat / samples
 * (render/film_resolve.cpp resolves it), the splat scaled like pbrt-v4's film splats.
 *
 * OpenCL 1.2 on PoCL 3.1 has no float atomic add, so a splat is a compare-and-swap loop on the
 * float's bits (atomic_cmpxchg; on the host the GCC/Clang __atomic built-in on the same 32-bit
 * word). The order in which concurrent splats land decides how their sum rounds: a render that
 * splats is reproducible to float rounding, not bit for bit. Only the own-pixel accumulation is
 * bit-reproducible (one work-item owns it, and adds its samples in sample order). */
#ifndef KERNELS_FILM_H
#define KERNELS_FILM_H

#include "single_source/vocabulary.h"

#ifdef __OPENCL_C_VERSION__
SS_FN float film_bits_to_float(uint bits) { return as_float(bits); }
SS_FN uint film_float_to_bits(float value) { return as_uint(value); }
/* Returns the word's value before the exchange, as atomic_cmpxchg does. */
SS_FN uint film_compare_exchange(GLOBAL_MEM uint* word, uint expected, uint desired) {
    return atomic_cmpxchg((volatile GLOBAL_MEM uint*)word, expected, desired);
}
#else
SS_FN float film_bits_to_float(uint bits) {
    float value;
    __builtin_memcpy(&value, &bits, sizeof value);
    return value;
}
SS_FN uint film_float_to_bits(float value) {
    uint bits;
    __builtin_memcpy(&bits, &value, sizeof bits);
    return bits;
}
SS_FN uint film_compare_exchange(uint* word, uint expected, uint desired) {
    __atomic_compare_exchange_n(word, &expected, desired, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
    return expected; /* on failure the built-in stores the value it found */
}
#endif

/* A pixel's sum of squares with one more finite sample `l` (the caller keeps non-finite ones out,
 * as it does of the sum). */
SS_FN float4 film_add_square(float4 squares, float3 l) { return squares + make_float4(l.x * l.x, l.y * l.y, l.z * l.z, 0.0f); }

/* Adds `value` to one float of the splat buffer, whoever else adds to it at the same time. */
SS_FN void film_atomic_add(GLOBAL_MEM uint* word, float value) {
    uint seen = *word;
    for (;;) {
        uint desired = film_float_to_bits(film_bits_to_float(seen) + value);
        uint before = film_compare_exchange(word, seen, desired);
        if (before == seen) return;
        seen = before;
    }
}

/* Splats radiance onto the pixel under raster position (x, y) (pixels from the top-left corner);
 * positions off the film are dropped. Non-finite values are dropped too, and counted by the caller. */
SS_FN void film_splat(GLOBAL_MEM uint* splat, int width, int height, float x, float y, float3 value) {
    if (!(x >= 0.0f && y >= 0.0f && x < (float)width && y < (float)height)) return;
    int pixel = min((int)y, height - 1) * width + min((int)x, width - 1);
    film_atomic_add(splat + 3 * pixel, value.x);
    film_atomic_add(splat + 3 * pixel + 1, value.y);
    film_atomic_add(splat + 3 * pixel + 2, value.z);
}

#endif
