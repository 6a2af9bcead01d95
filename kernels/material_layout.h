/* The Material layout as this compiler sees it, for every kernel that reads a Material buffer:
 * the host compares it with its own before use (kernels/host/material_layout.hpp). */
#ifndef KERNELS_MATERIAL_LAYOUT_H
#define KERNELS_MATERIAL_LAYOUT_H
#include "brdf/material.h"

__kernel void brdf_material_layout(__global int* out) {
    if (get_global_id(0) != 0) return;
    out[0] = (int)sizeof(Material);
    out[1] = (int)__builtin_offsetof(Material, roughness);
    out[2] = (int)__builtin_offsetof(Material, ior);
    out[3] = (int)__builtin_offsetof(Material, model);
    out[4] = (int)__builtin_offsetof(Material, distribution);
}

#endif
