/* Bidirectional path tracing on OpenCL (kernels/bdpt.h): one work-item per pixel, each launch adding
 * `sample_count` samples to every pixel of the film, t = 1 connections splatted anywhere on it. The
 * arguments are the path tracer's (kernels/path_tracer.cl), bound the same way. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/materials.h" /* the feature switches, before any brdf/ header */
#include "scene/generated.h"

#include "kernels/material_layout.h"
#include "kernels/bdpt.h"

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
