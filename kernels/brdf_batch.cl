/* The BRDF module over arrays, for the host's agreement test and throughput figures: item i uses
 * materials[material_index[i]] and directions stored as 3 floats each (not float3 buffers, whose
 * elements are 16 bytes in OpenCL C and 12 in the host's glm::vec3). */

/* No fused multiply-add: the host build (x86-64 baseline, no FMA) rounds every product, and the
 * agreement test compares the two builds to 1e-5. */
#pragma OPENCL FP_CONTRACT OFF

#include "brdf/bsdf.h"
#include "kernels/material_layout.h"

static float3 load_direction(__global const float* a, int i) {
    return (float3)(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

static void store_direction(__global float* a, int i, float3 v) {
    a[3 * i] = v.x;
    a[3 * i + 1] = v.y;
    a[3 * i + 2] = v.z;
}

__kernel void brdf_eval(int count, __global const Material* materials, __global const float* tables,
                        __global const int* material_index,
                        __global const float* wo, __global const float* wi, __global float* f) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    Material m = materials[material_index[i]]; /* bsdf_* take private pointers */
    store_direction(f, i, bsdf_eval_tables(&m, tables, load_direction(wo, i), load_direction(wi, i)));
}

__kernel void brdf_pdf(int count, __global const Material* materials, __global const float* tables,
                        __global const int* material_index,
                       __global const float* wo, __global const float* wi, __global float* pdf) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    Material m = materials[material_index[i]];
    pdf[i] = bsdf_pdf_tables(&m, tables, load_direction(wo, i), load_direction(wi, i));
}

__kernel void brdf_sample(int count, __global const Material* materials, __global const float* tables,
                        __global const int* material_index,
                          __global const float* wo, __global const float* u, __global float* wi, __global float* f,
                          __global float* pdf, __global int* flags) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    Material m = materials[material_index[i]];
    BsdfSample s = bsdf_sample_tables(&m, tables, load_direction(wo, i), load_direction(u, i));
    store_direction(wi, i, s.wi);
    store_direction(f, i, s.f);
    pdf[i] = s.pdf;
    flags[i] = s.flags;
}
