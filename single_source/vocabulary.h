/* Shared vocabulary of the single-source modules (brdf, sdf, ibl, kernels).
 * Every such header is written in the common subset of OpenCL C 1.2 and C++17: no references,
 * no overloading, no templates; vectors are float3 built with make_float3(); functions are SS_FN
 * ("single source"). On the host, single_source/host_vocabulary.hpp supplies float3 and the
 * built-ins; in a kernel, OpenCL does. */
#ifndef SINGLE_SOURCE_VOCABULARY_H
#define SINGLE_SOURCE_VOCABULARY_H

#ifdef __OPENCL_C_VERSION__
#define SS_FN static inline
/* For a function the compiler would keep out of line: the private structs a call passes by address
 * (the scene, the settings) must then be kept in memory, which PoCL does once per work-item. */
#define SS_INLINE_ALWAYS __attribute__((always_inline))
#define make_float2(x, y) ((float2)((x), (y)))
#define make_float3(x, y, z) ((float3)((x), (y), (z)))
#define make_float4(x, y, z, w) ((float4)((x), (y), (z), (w)))
#define isfinite_f(x) isfinite(x)
/* Address spaces of buffer pointers; the host has one flat address space. */
#define GLOBAL_MEM __global
#define CONSTANT_MEM __constant
/* a loop to unroll, inside a macro (kernels/rng.h) */
#define SS_PRAGMA_UNROLL _Pragma("unroll")
#else
#define SS_FN inline
#define SS_INLINE_ALWAYS
#define GLOBAL_MEM
#define CONSTANT_MEM
#define SS_PRAGMA_UNROLL
#endif

/* The distance functions' component forms (sdf/, fX_xyz) compute in SDF_FLOAT: one float, or with
 * SDF_LANES = 8 (a packet kernel, kernels/march_packets.cl) a float8 of eight rays at once, so that
 * the march runs on the CPU's vector lanes whatever PoCL's work-item vectoriser makes of the code.
 * A condition on such values is an SDF_MASK (int 0 / non-0, or int8 0 / -1 per lane), used through
 * select() and SDF_ANY(); SDF_SUM() adds the lanes; SDF_UINT holds the lanes' 32-bit words (random
 * numbers, kernels/rng.h). Written once, these functions read the same for both. */
#ifndef SDF_LANES
#define SDF_FLOAT float
#define SDF_MASK int
#define SDF_UINT uint
#define SDF_ANY(mask) ((mask) != 0)
#define SDF_SUM(x) (x)
#elif SDF_LANES == 8
#define SDF_FLOAT float8
#define SDF_MASK int8
#define SDF_UINT uint8
#define SDF_ANY(mask) any(mask)
#define SDF_SUM(x) ((((x).s0 + (x).s1) + ((x).s2 + (x).s3)) + (((x).s4 + (x).s5) + ((x).s6 + (x).s7)))
#else
#error "SDF_LANES: 8 or undefined"
#endif

#define SS_PI 3.14159265358979323846f
#define SS_INV_PI 0.31830988618379067154f
#define SS_INV_4PI 0.07957747154594766788f

SS_FN float sqr(float x) { return x * x; }
SS_FN float safe_sqrt(float x) { return sqrt(fmax(x, 0.0f)); }
SS_FN float pow5(float x) { float x2 = x * x; return x2 * x2 * x; }
SS_FN float3 float3_splat(float v) { return make_float3(v, v, v); }
SS_FN float max_component(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }
SS_FN float mean3(float3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }
/* A float3 from a plain array: structs shared with the host store vectors as float[3], which has
 * one layout on both sides (an OpenCL float3 is 16 bytes). */
SS_FN float3 float3_from_array(const float v[3]) { return make_float3(v[0], v[1], v[2]); }
SS_FN void float3_to_array(float3 v, float out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}
SS_FN bool finite3(float3 v) { return isfinite_f(v.x) && isfinite_f(v.y) && isfinite_f(v.z); }

#endif
