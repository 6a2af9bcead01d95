/* The path tracer on OpenCL (kernels/path_tracer.h): render_pt, one work-item per pixel, each launch
 * adding `sample_count` samples to every pixel of the film (kernels/film.h); or render_pt_step, the
 * wavefront's step (kernels/path_tracer_wavefront.h), whose marches run in packet kernels. Every integrator kernel takes
 * the same arguments, so the host (render/opencl_renderer) binds them the same way; a kernel launched
 * over a range of pixels or paths takes the range's first as its last argument, not as a global
 * offset (render/opencl_launch.hpp). */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/materials.h" /* the feature switches, before any brdf/ header */
#include "scene/generated.h"

#include "kernels/material_layout.h"
#include "kernels/path_tracer_wavefront.h"

__kernel void render_pt(RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4* env_texels,
                        __global const AliasEntry* env_alias,
                        __global const Material* materials, __global const float* tables, __global const float4* emission, __global const Light* lights,
                        __global const float* light_cdf, __global const int* light_of_slot, __global float4* accumulation, __global float4* squares,
                        __global uint* splat, __global uint* ray_counts, __global uint* lost_ray_counts, int first_pixel) {
    int pixel = first_pixel + (int)get_global_id(0);
    if (pixel >= camera.width * camera.height) return;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    (void)splat; /* the path tracer adds to its own pixel only */
    path_tracer_pixel(&settings, &camera, &scene, pixel, accumulation, squares, ray_counts, lost_ray_counts);
}

/* The wavefront's camera step and its later steps (kernels/path_tracer_wavefront.h): render_pt's
 * arguments, then the wavefront's buffers, the same for both so that the host binds them alike
 * (the step adds its `first` flag); work-item p steps path p. */
#define WAVEFRONT_KERNEL_ARGUMENTS                                                                                                        \
    RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4 *env_texels,                                \
        __global const AliasEntry *env_alias, __global const Material *materials, __global const float *tables,                       \
        __global const float4 *emission, __global const Light *lights, __global const float *light_cdf, __global const int *light_of_slot, \
        __global float4 *accumulation, __global float4 *squares, __global uint *splat, __global uint *ray_counts,                        \
        __global uint *lost_ray_counts, int stride,                                                                                        \
        __global PathState *states, __global float *rays, __global float *shadow_rays, __global const RayMarch *ray_marches,              \
        __global const RayMarch *shadow_marches, __global volatile uint *unfinished, int slots, __global float4 *path_radiance,          \
        __global uint *path_rays, __global uint *path_lost_rays, __global uint *camera_rngs

/* A step of every path, path_tracer_step; `first` (iteration 1) begins the paths. One kernel for
 * both, the step's flag an argument: the scatter is most of the program's code, and a kernel of its
 * own for the first step would have PoCL compile it twice for every scene and material. */
__kernel void render_pt_step(WAVEFRONT_KERNEL_ARGUMENTS, int first, int first_path) {
    int path = first_path + (int)get_global_id(0);
    if (path >= slots * camera.width * camera.height) return;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    WavefrontFilm film = {slots, accumulation, squares, ray_counts, lost_ray_counts, path_radiance, path_rays, path_lost_rays};
    (void)splat;
    path_tracer_step(&settings, &camera, &scene, path, states, stride, rays, shadow_rays, ray_marches, shadow_marches, camera_rngs, film,
                     unfinished, first != 0);
}

/* The camera rays of a camera that the packets do not begin themselves (a thin lens). */
__kernel void render_pt_camera(WAVEFRONT_KERNEL_ARGUMENTS, int first_path) {
    int path = first_path + (int)get_global_id(0);
    if (path >= slots * camera.width * camera.height) return;
    (void)env, (void)env_texels, (void)env_alias, (void)materials, (void)tables, (void)emission, (void)lights, (void)light_cdf;
    (void)light_of_slot, (void)accumulation, (void)squares, (void)splat, (void)ray_counts, (void)lost_ray_counts, (void)states, (void)shadow_rays;
    (void)ray_marches, (void)shadow_marches, (void)unfinished, (void)path_radiance, (void)path_rays, (void)path_lost_rays;
    path_tracer_camera_step(&settings, &camera, path, stride, rays, camera_rngs);
}

/* After a launch of several samples in flight: adds each pixel's paths to the film in sample order
 * (path_tracer_resolve). */
__kernel void render_pt_resolve(int pixels, int slots, __global float4* accumulation, __global float4* squares, __global uint* ray_counts,
                                __global uint* lost_ray_counts, __global float4* path_radiance, __global uint* path_rays,
                                __global uint* path_lost_rays) {
    int pixel = (int)get_global_id(0);
    if (pixel >= pixels) return;
    WavefrontFilm film = {slots, accumulation, squares, ray_counts, lost_ray_counts, path_radiance, path_rays, path_lost_rays};
    path_tracer_resolve(pixels, pixel, film);
}
