/* Shared vocabulary of the single-source modules (brdf, sdf, ibl, kernels).
 * Every such header is written in the common subset of OpenCL C 1.2 and C++17: no references,
 * no overloading, no templates; vectors are float3 built with make_float3(); functions are BRDF_FN.
 * On the host, brdf/host/glm_builtins.hpp supplies float3 and the built-ins; in a kernel, OpenCL does. */
#ifndef BRDF_COMMON_H
#define BRDF_COMMON_H

#ifdef __OPENCL_C_VERSION__
#define BRDF_FN static inline
#define make_float2(x, y) ((float2)((x), (y)))
#define make_float3(x, y, z) ((float3)((x), (y), (z)))
#define make_float4(x, y, z, w) ((float4)((x), (y), (z), (w)))
#define isfinite_f(x) isfinite(x)
/* Address spaces of buffer pointers; the host has one flat address space. */
#define GLOBAL_MEM __global
#define CONSTANT_MEM __constant
#else
#define BRDF_FN inline
#define GLOBAL_MEM
#define CONSTANT_MEM
#endif

#define BRDF_PI 3.14159265358979323846f
#define BRDF_INV_PI 0.31830988618379067154f
#define BRDF_INV_4PI 0.07957747154594766788f

BRDF_FN float sqr(float x) { return x * x; }
BRDF_FN float safe_sqrt(float x) { return sqrt(fmax(x, 0.0f)); }
BRDF_FN float pow5(float x) { float x2 = x * x; return x2 * x2 * x; }
BRDF_FN float3 float3_splat(float v) { return make_float3(v, v, v); }
BRDF_FN float max_component(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }
BRDF_FN bool finite3(float3 v) { return isfinite_f(v.x) && isfinite_f(v.y) && isfinite_f(v.z); }

#endif
