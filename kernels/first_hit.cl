/* The first-hit AOVs on OpenCL (kernels/first_hit.h): render_first_hits, one work-item per pixel,
 * adds samples settings.first_sample .. + sample_count to the pixel's sums, and writes the slot
 * that sample `slot_sample` sees when it is among them. A program of its own,
 * built only when a render asks for AOVs (render/opencl_renderer.cpp), so a render without them
 * compiles none of this. Takes render_pt's arguments first, so the host binds them the same way. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/materials.h" /* the feature switches, before any brdf/ header */
#include "scene/generated.h"

#include "kernels/first_hit.h"

__kernel void render_first_hits(RenderKernelSettings settings, Camera camera, EnvironmentMap env, __global const float4* env_texels,
                                __global const AliasEntry* env_alias, __global const Material* materials, __global const float* tables,
                                __global const float4* emission, __global const Light* lights, __global const float* light_cdf,
                                __global const int* light_of_slot, __global float4* accumulation, __global float4* squares, __global uint* splat,
                                __global uint* ray_counts, __global uint* lost_ray_counts, __global float4* albedo_sums,
                                __global float4* normal_depth_sums, int slot_sample, __global int* slots, int first_pixel) {
    int pixel = first_pixel + (int)get_global_id(0);
    if (pixel >= camera.width * camera.height) return;
    (void)accumulation, (void)squares, (void)splat, (void)ray_counts, (void)lost_ray_counts;
    RenderScene scene = render_scene_make(materials, tables, emission, lights, light_cdf, light_of_slot, env, env_texels, env_alias);
    float4 albedo = albedo_sums[pixel], normal_depth = normal_depth_sums[pixel];
    for (int i = 0; i < settings.sample_count; ++i) {
        FirstHit h = first_hit_sample(&settings, &camera, &scene, pixel, settings.first_sample + i);
        albedo += make_float4(h.albedo.x, h.albedo.y, h.albedo.z, h.coverage);
        normal_depth += make_float4(h.normal.x, h.normal.y, h.normal.z, h.depth);
        if (settings.first_sample + i == slot_sample) slots[pixel] = h.slot;
    }
    albedo_sums[pixel] = albedo;
    normal_depth_sums[pixel] = normal_depth;
}
