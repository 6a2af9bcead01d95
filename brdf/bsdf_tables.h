/* The BSDF's tables in global memory: one float array that kernels receive as a buffer argument and
 * the host reads from its registry (brdf/host/measured_registry.hpp), the same offsets in both.
 *   [BSDF_TABLES_ANISOTROPIC_ALBEDO]   the anisotropic GGX energy table's E(w) (brdf/energy_grid.h),
 *                                      16-bit codes, two to a float;
 *   [BSDF_TABLES_ANISOTROPIC_AVERAGE]  its E_avg over [ratio][roughness], floats;
 *   [BSDF_TABLES_MEASURED]             the measured materials' blocks (brdf/measured.h), each at its
 *                                      material's measured_offset.
 * The anisotropic table is 66 KB, more than the 64 KB of __constant memory OpenCL guarantees a kernel
 * with every other table besides (docs/materials.md), so it is read from global memory; the other
 * energy tables stay in __constant. */
#ifndef BRDF_BSDF_TABLES_H
#define BRDF_BSDF_TABLES_H
#include "single_source/vocabulary.h"
#include "energy_grid.h"

#define ANISO_TABLE_ENTRIES (ANISO_GRID_RATIO * ANISO_GRID_PHI * ANISO_GRID_ROUGHNESS * ANISO_GRID_MU)
#define BSDF_TABLES_ANISOTROPIC_ALBEDO 0
#define BSDF_TABLES_ANISOTROPIC_AVERAGE (BSDF_TABLES_ANISOTROPIC_ALBEDO + (ANISO_TABLE_ENTRIES + 1) / 2)
#define BSDF_TABLES_MEASURED (BSDF_TABLES_ANISOTROPIC_AVERAGE + ANISO_GRID_RATIO * ANISO_GRID_ROUGHNESS)

SS_FN GLOBAL_MEM const ushort* bsdf_tables_anisotropic_albedo(GLOBAL_MEM const float* tables) {
    return (GLOBAL_MEM const ushort*)(tables + BSDF_TABLES_ANISOTROPIC_ALBEDO);
}

#ifndef __OPENCL_C_VERSION__
/* The host's tables: the registry's array as of now (brdf/host/measured_registry.cpp). */
const float* bsdf_tables();
#endif

#endif
