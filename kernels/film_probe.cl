/* Splats given as (x, y, value) triples onto the film's splat buffer from many work-items at once,
 * for the test that concurrent splats lose nothing (kernels/film.h). */
#include "kernels/film.h"

__kernel void film_splat_probe(int count, __global const float* splats, __global uint* splat, int width, int height) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    float v = splats[3 * i + 2];
    film_splat(splat, width, height, splats[3 * i], splats[3 * i + 1], make_float3(v, 2.0f * v, 0.5f * v));
}
