/* A compiled scene's distance field at given points, for the test that the OpenCL build agrees with
 * the host interpreter (scene/interpreter.hpp). Points and normals are 3 floats each (not float3
 * buffers, whose elements are 16 bytes in OpenCL C and 12 in the host's glm::vec3). */

/* No fused multiply-add: the host build rounds every product. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/generated.h"

__kernel void scene_probe(int count, __global const float* points, __global float* distance, __global int* material,
                          __global int* has_normal, __global float* normal) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    float3 p = (float3)(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    int m;
    distance[i] = scene_distance_material(p, &m);
    material[i] = m;
    float3 n = (float3)(0.0f, 0.0f, 0.0f);
    has_normal[i] = scene_analytic_normal(p, &n);
    normal[3 * i] = n.x;
    normal[3 * i + 1] = n.y;
    normal[3 * i + 2] = n.z;
}
