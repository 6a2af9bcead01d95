/* Bidirectional path tracing on OpenCL. render_bdpt (kernels/bdpt.h, `bdpt` and `lt`): one
 * work-item per pixel, each launch adding `sample_count` samples to every pixel of the film, t = 1
 * connections splatted anywhere on it; the arguments are the path tracer's (kernels/path_tracer.cl),
 * bound the same way. The light-vertex cache's kernels (kernels/bdpt_cache.h, `bdpt-cache`), per
 * sample index: the light pass (one work-item per light subpath), the offsets (one work-item), then
 * the camera pass (one work-item per pixel, the path tracer's arguments, then the cache's); vcm's
 * grid (kernels/vcm.h) between the last two. One program for the four integrators: PoCL builds it
 * once for all of them. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/materials.h" /* the feature switches, before any brdf/ header */
#include "scene/generated.h"

#include "kernels/material_layout.h"
#include "kernels/bdpt_cache.h"

__kernel void render_bdpt(RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4* env_texels,
                          __global const AliasEntry* env_alias,
                          __global const Material* materials, __global const float* tables, __global const float4* emission, __global const Light* lights,
                          __global const float* light_cdf, __global const int* light_of_slot, __global float4* accumulation,
                          __global float4* squares, __global uint* splat, __global uint* ray_counts, __global uint* lost_ray_counts, int first_pixel) {
    int pixel = first_pixel + (int)get_global_id(0);
    if (pixel >= camera.width * camera.height) return;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    bdpt_pixel(&settings, &camera, &scene, pixel, accumulation, squares, splat, ray_counts, lost_ray_counts);
}

/* the renderers size the cache's vertex buffer with BDPT_CACHE_VERTEX_BYTES */
typedef char bdpt_cache_vertex_fits[sizeof(PathVertex) <= BDPT_CACHE_VERTEX_BYTES ? 1 : -1];

__kernel void render_bdpt_cache_light(RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4* env_texels,
                                      __global const AliasEntry* env_alias, __global const Material* materials, __global const float* tables,
                                      __global const float4* emission, __global const Light* lights, __global const float* light_cdf,
                                      __global const int* light_of_slot, __global float4* accumulation, __global float4* squares,
                                      __global uint* splat, __global uint* ray_counts, __global uint* lost_ray_counts,
                                      __global PathVertex* cache, __global int* lengths, __global uint* offsets, int paths, int splats,
                                      int first_path) {
    int path = first_path + (int)get_global_id(0);
    if (path >= paths) return;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    bdpt_cache_light_path(&settings, &camera, &scene, path, paths, cache, lengths, offsets, splat, splats, ray_counts, lost_ray_counts);
}

__kernel void render_bdpt_cache_offsets(__global uint* offsets, int paths) {
    if (get_global_id(0) == 0) bdpt_cache_offsets(offsets, paths);
}

/* The camera pass of bdpt-cache and vcm (kernels/vcm.h): vcm's hash grid over the pool (built
 * between the light and camera passes by render_vcm_grid, one work-item, in the cache's order: the
 * same entries on every device) in cells and entries; bdpt-cache passes size 0 and merges nothing. */
__kernel void render_bdpt_cache(RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4* env_texels,
                                __global const AliasEntry* env_alias, __global const Material* materials, __global const float* tables,
                                __global const float4* emission, __global const Light* lights, __global const float* light_cdf,
                                __global const int* light_of_slot, __global float4* accumulation, __global float4* squares,
                                __global uint* splat, __global uint* ray_counts, __global uint* lost_ray_counts,
                                __global const PathVertex* cache, __global const int* lengths, __global const uint* offsets, int paths,
                                int connections, __global const uint* cells, __global const uint* entries, uint size, int first_pixel) {
    int pixel = first_pixel + (int)get_global_id(0);
    if (pixel >= camera.width * camera.height) return;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    bdpt_cache_pixel(&settings, &camera, &scene, pixel, cache, lengths, offsets, paths, connections, cells, entries, size, accumulation, squares,
                     ray_counts, lost_ray_counts);
}

__kernel void render_vcm_grid(RenderKernelSettings settings, __global const PathVertex* cache, __global const int* lengths, int paths,
                              __global uint* cells, __global uint* entries, uint size) {
    if (get_global_id(0) == 0) vcm_build_grid(&settings, cache, lengths, paths, cells, entries, size);
}
