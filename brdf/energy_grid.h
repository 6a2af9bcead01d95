/* The grid of the energy-compensation tables (brdf/energy_table_*.h, written by
 * tools/generate_energy_tables from validation/energy_tables.cpp): directional albedo E(mu) of the single-scattering
 * microfacet reflection with F = 1 over mu = cos theta, perceptual roughness and (Hyper-Cauchy) shape,
 * and its cosine-weighted average. Lookups interpolate linearly between the nodes. */
#ifndef BRDF_ENERGY_GRID_H
#define BRDF_ENERGY_GRID_H
#include "single_source/vocabulary.h"
#include "material.h"

#define ENERGY_GRID_MU 32        /* nodes at mu = (j / 31)^2: dense at grazing, where E(mu) turns fastest */
#define ENERGY_GRID_ROUGHNESS 32 /* nodes at roughness = i / 31 */
#define ENERGY_GRID_SHAPE 8      /* nodes even in t = 1 / (g - 1) over [1/15, 1/0.6] */

/* The mu grids of all tables have nodes even in sqrt(mu): E(mu) falls from its limit at mu = 0 to its
 * minimum within a few degrees of grazing, and a grid even in mu cuts that corner, reflecting up to
 * 0.2 % too much at 89.9 degrees once compensated. Node j of n is at mu = (j / (n - 1))^2. */
SS_FN float energy_grid_mu_node(int j, int n) {
    float s = (float)j / (float)(n - 1);
    return s * s;
}
SS_FN float energy_grid_mu(int j) { return energy_grid_mu_node(j, ENERGY_GRID_MU); }
SS_FN float energy_grid_roughness(int i) { return (float)i / (float)(ENERGY_GRID_ROUGHNESS - 1); }

SS_FN float energy_grid_shape_t(float g) { return 1.0f / (g - 1.0f); }
SS_FN float energy_grid_shape(int k) {
    float t_lo = energy_grid_shape_t(BRDF_HC_SHAPE_MAX), t_hi = energy_grid_shape_t(BRDF_HC_SHAPE_MIN);
    return 1.0f + 1.0f / (t_lo + (t_hi - t_lo) * (float)k / (float)(ENERGY_GRID_SHAPE - 1));
}

/* The anisotropic GGX table (brdf/energy_table_ggx_anisotropic.h): E(w) over [ratio][phi][roughness][mu]
 * and E_avg over [ratio][roughness], for alpha_x >= alpha_y (the lookup swaps the axes otherwise).
 * ratio q = alpha_y / alpha_x and the azimuth phi of w from the longer axis at the nodes below (E is
 * even about both axes); roughness sqrt(alpha_rms), alpha_rms^2 = (alpha_x^2 + alpha_y^2) / 2, at
 * nodes even over [0, 1.5], which covers the lab model's Disney mapping (up to 1.499) and OpenPBR's
 * (alpha_rms = roughness^2, so at most 1); mu even in sqrt(mu) like the others. 66 KB: kernels read
 * it from global memory (brdf/bsdf_tables.h), docs/materials.md says what its resolution buys. */
#define ANISO_GRID_RATIO 8
#define ANISO_GRID_PHI 11
#define ANISO_GRID_ROUGHNESS 24
#define ANISO_GRID_MU 16
#define ANISO_GRID_ROUGHNESS_MAX 1.5f

/* The value at fractional node coordinate x of n increasing nodes (piecewise linear through them),
 * and the coordinate of v, clamped to the nodes. */
SS_FN float energy_grid_nodes_value(CONSTANT_MEM const float* nodes, int n, float x) {
    int k = clamp((int)x, 0, n - 2);
    return mix(nodes[k], nodes[k + 1], x - (float)k);
}
SS_FN float energy_grid_nodes_coordinate(CONSTANT_MEM const float* nodes, int n, float v) {
    v = clamp(v, nodes[0], nodes[n - 1]);
    int k = 0;
    while (k < n - 2 && v >= nodes[k + 1]) ++k;
    return (float)k + (v - nodes[k]) / (nodes[k + 1] - nodes[k]);
}

/* The ratio nodes, dense below 0.5, where E near grazing turns fastest with q; the azimuth nodes
 * (degrees), dense towards the shorter axis at 90, where the projected roughness of a strongly
 * anisotropic lobe falls within a few degrees (docs/materials.md, "Anisotropic compensation"). */
CONSTANT_MEM const float anisotropic_grid_ratio_nodes[ANISO_GRID_RATIO] = {0.0f, 0.1f, 0.175f, 0.25f, 0.375f, 0.5f, 0.75f, 1.0f};
CONSTANT_MEM const float anisotropic_grid_phi_nodes[ANISO_GRID_PHI] = {0.0f, 20.0f, 35.0f, 47.0f, 57.0f, 65.0f, 72.0f, 78.0f, 83.0f, 87.0f, 90.0f};

SS_FN float anisotropic_grid_ratio(float x) { return energy_grid_nodes_value(anisotropic_grid_ratio_nodes, ANISO_GRID_RATIO, x); }
SS_FN float anisotropic_grid_ratio_coordinate(float q) {
    return energy_grid_nodes_coordinate(anisotropic_grid_ratio_nodes, ANISO_GRID_RATIO, q);
}
/* phi in radians */
SS_FN float anisotropic_grid_phi(float x) { return energy_grid_nodes_value(anisotropic_grid_phi_nodes, ANISO_GRID_PHI, x) * (SS_PI / 180.0f); }
SS_FN float anisotropic_grid_phi_coordinate(float phi) {
    return energy_grid_nodes_coordinate(anisotropic_grid_phi_nodes, ANISO_GRID_PHI, phi * (180.0f / SS_PI));
}

/* alpha_x and alpha_y of ratio node coordinate q (alpha_y / alpha_x) and rms roughness r. */
SS_FN float anisotropic_grid_alpha_x(float q, float r) { return r * r * sqrt(2.0f / (1.0f + q * q)); }

/* The dielectric's tables (brdf/energy_table_dielectric.h, GGX): E over [side][ior][roughness][mu],
 * nodes even in 1 / ior over [1/3, 1] (denser where glass and water are), in roughness, and in sqrt(mu)
 * over [0, 1] like the conductors'. The node at ior 1 holds the rough interface of ior 1.01: an index-matched one is smooth. */
#define DIELECTRIC_GRID_IOR 10
#define DIELECTRIC_GRID_ROUGHNESS 16
#define DIELECTRIC_GRID_MU 24

/* Node k of n even nodes over [lo, hi], and the fractional node coordinate of v, clamped to the grid. */
SS_FN float energy_grid_node(int k, float lo, float hi, int n) { return lo + (hi - lo) * (float)k / (float)(n - 1); }
SS_FN float energy_grid_node_coordinate(float v, float lo, float hi, int n) {
    return clamp((v - lo) / (hi - lo) * (float)(n - 1), 0.0f, (float)(n - 1));
}

SS_FN float energy_grid_ior(int k) {
    return 1.0f / energy_grid_node(DIELECTRIC_GRID_IOR - 1 - k, 1.0f / BRDF_IOR_MAX, 1.0f / BRDF_IOR_MIN, DIELECTRIC_GRID_IOR);
}
SS_FN float energy_grid_ior_coordinate(float eta) {
    return (float)(DIELECTRIC_GRID_IOR - 1) -
           energy_grid_node_coordinate(1.0f / eta, 1.0f / BRDF_IOR_MAX, 1.0f / BRDF_IOR_MIN, DIELECTRIC_GRID_IOR);
}

/* The fractional node coordinate of mu on an n-node mu grid. */
SS_FN float energy_grid_mu_coordinate_of(float mu, int n) { return energy_grid_node_coordinate(sqrt(clamp(mu, 0.0f, 1.0f)), 0.0f, 1.0f, n); }
SS_FN float energy_grid_mu_coordinate(float mu) { return energy_grid_mu_coordinate_of(mu, ENERGY_GRID_MU); }
SS_FN float energy_grid_roughness_coordinate(float roughness) {
    return energy_grid_node_coordinate(roughness, 0.0f, 1.0f, ENERGY_GRID_ROUGHNESS);
}
SS_FN float energy_grid_shape_coordinate(float g) {
    float t_lo = energy_grid_shape_t(BRDF_HC_SHAPE_MAX), t_hi = energy_grid_shape_t(BRDF_HC_SHAPE_MIN);
    return clamp((energy_grid_shape_t(g) - t_lo) / (t_hi - t_lo) * (float)(ENERGY_GRID_SHAPE - 1), 0.0f,
                 (float)(ENERGY_GRID_SHAPE - 1));
}

/* Linear interpolation of a row of n values at fractional index x in [0, n - 1]. */
SS_FN float energy_grid_lerp(CONSTANT_MEM const float* row, int n, float x) {
    int i = min((int)x, n - 2);
    float t = x - (float)i;
    return mix(row[i], row[i + 1], t);
}

/* The albedo tables E(mu) are stored in 16 bits, E = q / 65535, q rounded up by the generator
 * (validation/energy_tables.cpp), so the stored E is never below the estimate and compensation stays
 * conservative; a step of 1.5e-5 is far below the estimate's own error. Half the size of floats keeps
 * every table a kernel can hold under the 64 KB of __constant memory OpenCL guarantees (docs/materials.md). */
#define ENERGY_TABLE_ONE 65535.0f
SS_FN float energy_code_albedo(ushort code) { return (float)code * (1.0f / ENERGY_TABLE_ONE); }
SS_FN float energy_grid_albedo_value(CONSTANT_MEM const ushort* table, int index) { return energy_code_albedo(table[index]); }

/* energy_grid_lerp() of a stored albedo row. */
SS_FN float energy_grid_lerp_albedo(CONSTANT_MEM const ushort* row, int n, float x) {
    int i = min((int)x, n - 2);
    float t = x - (float)i;
    return mix(energy_grid_albedo_value(row, i), energy_grid_albedo_value(row, i + 1), t);
}

/* 1 - E interpolated in a stored albedo row like energy_grid_lerp_albedo(): where E is within 1e-4 of
 * 1 (smooth lobes near grazing), interpolating 1 - E keeps what compensation gives back exact at the
 * nodes and to float precision between them, where E's last bits, which the OpenCL build rounds
 * otherwise (contracted multiply-adds), would be a relative error of 1e-3 in 1 - E. */
SS_FN float energy_grid_lerp_lost(GLOBAL_MEM const ushort* row, int n, float x) {
    int i = min((int)x, n - 2);
    float t = x - (float)i;
    return mix(1.0f - energy_code_albedo(row[i]), 1.0f - energy_code_albedo(row[i + 1]), t);
}

/* E(mu) of a (roughness, mu) table of ENERGY_GRID_ROUGHNESS rows, interpolated in both. */
SS_FN float energy_table_albedo(CONSTANT_MEM const ushort* table, float r, float mu) {
    float x = energy_grid_roughness_coordinate(r);
    int i = min((int)x, ENERGY_GRID_ROUGHNESS - 2);
    float m = energy_grid_mu_coordinate(mu);
    float lo = energy_grid_lerp_albedo(table + i * ENERGY_GRID_MU, ENERGY_GRID_MU, m);
    float hi = energy_grid_lerp_albedo(table + (i + 1) * ENERGY_GRID_MU, ENERGY_GRID_MU, m);
    return mix(lo, hi, x - (float)i);
}

/* E(mu) of an [ior][roughness][mu] table on the dielectric grid, interpolated in all three. */
SS_FN float energy_grid_ior_albedo(CONSTANT_MEM const ushort* table, float r, float eta, float mu) {
    float x = energy_grid_ior_coordinate(eta);
    int k = min((int)x, DIELECTRIC_GRID_IOR - 2);
    float y = energy_grid_node_coordinate(r, 0.0f, 1.0f, DIELECTRIC_GRID_ROUGHNESS);
    int i = min((int)y, DIELECTRIC_GRID_ROUGHNESS - 2);
    float z = energy_grid_mu_coordinate_of(mu, DIELECTRIC_GRID_MU);
    float e[2];
    for (int dk = 0; dk < 2; ++dk) {
        CONSTANT_MEM const ushort* slice = table + ((k + dk) * DIELECTRIC_GRID_ROUGHNESS + i) * DIELECTRIC_GRID_MU;
        e[dk] = mix(energy_grid_lerp_albedo(slice, DIELECTRIC_GRID_MU, z), energy_grid_lerp_albedo(slice + DIELECTRIC_GRID_MU, DIELECTRIC_GRID_MU, z),
                    y - (float)i);
    }
    return mix(e[0], e[1], x - (float)k);
}

/* E_avg of an [ior][roughness] table on the dielectric grid. */
SS_FN float energy_grid_ior_average(CONSTANT_MEM const float* table, float r, float eta) {
    float x = energy_grid_ior_coordinate(eta);
    int k = min((int)x, DIELECTRIC_GRID_IOR - 2);
    float y = energy_grid_node_coordinate(r, 0.0f, 1.0f, DIELECTRIC_GRID_ROUGHNESS);
    CONSTANT_MEM const float* row = table + k * DIELECTRIC_GRID_ROUGHNESS;
    return mix(energy_grid_lerp(row, DIELECTRIC_GRID_ROUGHNESS, y), energy_grid_lerp(row + DIELECTRIC_GRID_ROUGHNESS, DIELECTRIC_GRID_ROUGHNESS, y),
               x - (float)k);
}

#endif
