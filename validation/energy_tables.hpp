// The energy-compensation tables (brdf/energy_grid.h): the directional albedo E(mu) of the
// single-scattering microfacet reflection with F = 1, and its cosine-weighted average, at every
// node of the grid. tools/generate_energy_tables writes them to brdf/energy_table_*.h; the tests
// compare entries with an independent estimate and with a regeneration.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"

namespace lab::validation {

// The strata x strata of the committed tables: the generator's default. The dielectric's estimator
// (the lab's sampler, weights up to 1 but less evenly spread) gets twice as many per side.
inline constexpr int kEnergyTableStrata = 64;
inline constexpr int kDielectricStrataFactor = 2;

// E(mu) of the lab model's glossy lobe with F0 = 1 and compensation off, isotropic, by the lobe's
// own visible-normal sampler over a strata x strata midpoint grid (the weight f cos / pdf is at most
// 1, so the grid converges fast). 1 where the lobe is a mirror, and at mu = 0 (the limit).
double single_scattering_albedo(int distribution, float shape, float roughness, float mu, int strata);

// Rows first to last of a [roughness][mu] table of albedo(roughness, mu) over n_r nodes even in
// roughness and the n_mu-node mu grid (brdf/energy_grid.h), made conservative. Compensated lobes add
// 1 - E_table(mu), so a table below the true E (the interpolant between nodes, where E turns fast:
// at grazing, or with roughness) would reflect more light than it receives. So E is also estimated
// between the nodes (the midpoints in sqrt(mu) and in roughness, and the cells' centres); where one
// lies above the interpolant, the nodes around it are raised by the difference. That trades the gain
// for a loss no larger than the lift. Values are clamped to 1; the nodes' neighbours are computed too.
std::vector<float> energy_slice(const std::function<double(float roughness, float mu)>& albedo, int n_r, int n_mu, int threads,
                                int first, int last);

// The 16-bit code of a stored albedo (brdf/energy_grid.h): the least q with q / 65535 >= e, so the
// stored table is never below the estimate; and the value it stands for. compute_energy_tables()
// rounds its albedo tables up this way before it averages them, so E_avg is that of the stored rows.
unsigned short energy_table_code(float e);
float energy_table_round_up(float e);

// E_avg = 2 int_0^1 E(mu) mu dmu of one row of the table, integrating the interpolant the lookup uses.
float average_albedo(const float* row, int n = ENERGY_GRID_MU);

// E_s(mu) of the white rough GGX dielectric, reflection plus transmission, seen from side 0 (outside)
// or 1 (inside), compensation off: the lab's own estimator (validation/albedo.hpp) at strata x strata.
double dielectric_single_scattering_albedo(int side, float roughness, float ior, float mu, int strata);

// F_avg = 2 int_0^1 F(mu) mu dmu of the exact dielectric Fresnel reflectance, from outside.
float dielectric_fresnel_average_of(float ior);

// The integral of g(wi) mu_i dwi over the upper hemisphere by the midpoint rule in t = sqrt(mu_i)
// (n_t strata) and phi (n_phi): nodes dense towards the horizon, where a grazing lobe peaks.
double hemisphere_cosine_midpoint(int n_t, int n_phi, const std::function<double(brdf::float3 wi)>& g);

// OpenPBR's layers (brdf/openpbr_energy.h): E(mu) of the GGX reflection off a dielectric of index
// ior with its exact Fresnel reflectance (the coat and the dielectric specular, what each passes down
// is 1 - E), by the lobe's visible-normal sampler at strata x strata; the Fresnel reflectance itself
// where the interface is smooth.
double dielectric_reflection_albedo(float roughness, float ior, float mu, int strata);
// E(mu) / SHEEN_TABLE_SCALE of the fuzz's sheen lobe (brdf/sheen.h) by the midpoint rule over
// 2 strata x strata cells even in sqrt(mu_i) and phi.
double sheen_albedo(float roughness, float mu, int strata);
// The sheen's lobe peaks near the horizon at low roughness: its table takes more strata per side.
inline constexpr int kSheenStrataFactor = 4;

// E(w) of the GGX reflection with F = 1 of the anisotropic grid's node (brdf/energy_grid.h): ratio
// alpha_y / alpha_x, azimuth phi of wo from the x axis, rms roughness, mu; as single_scattering_albedo.
double anisotropic_albedo(float ratio, float phi, float roughness, float mu, int strata);

struct AnisotropicTables {
    std::vector<float> albedo;   // [ratio][phi][roughness][mu], conservative, rounded up
    std::vector<float> average;  // [ratio][roughness]: the hemispherical average of the interpolated E
};

// The slices over roughness and mu come from energy_slice(); the azimuth and the ratio are made
// conservative the same way, by E at the midpoints between their nodes (and the cells' centres).
AnisotropicTables compute_anisotropic_tables(int strata, int threads);
// Node (k, l)'s entries (ratio, azimuth): at(hq, hp) is the slice at half node (hq / 2, hp / 2), and the
// node's own slice is raised by the largest deficit of the midpoints beside it (before rounding up).
std::vector<float> anisotropic_node_entries(int k, int l, const std::function<const std::vector<float>&(int hq, int hp)>& at);
// The entries of the table's row [k][l][i][*] (ANISO_GRID_MU of them, before rounding up), from the
// estimates that row needs alone: what the generator writes there.
std::vector<float> anisotropic_table_row(int k, int l, int i, int strata, int threads);
// E_avg [k][i] of an albedo table [ratio][phi][roughness][mu]: the hemispherical average of its interpolant.
float anisotropic_table_average(const std::vector<float>& albedo, int k, int i);
std::string anisotropic_table_header(const AnisotropicTables& tables, int strata);

struct OpenPbrTables {
    std::vector<float> specular_albedo;   // [ior][roughness][mu] on the dielectric grid, rounded up
    std::vector<float> specular_average;  // [ior][roughness]
    std::vector<float> sheen_albedo;      // [roughness][mu] on the conductors' grid, E / SHEEN_TABLE_SCALE, rounded up
};

OpenPbrTables compute_openpbr_tables(int strata, int threads);
std::string openpbr_table_header(const OpenPbrTables& tables, int strata);

struct EnergyTables {
    std::vector<float> ggx_albedo;           // [roughness][mu], rounded up to 16 bits (energy_table_round_up)
    std::vector<float> ggx_average;          // [roughness]
    std::vector<float> hyper_cauchy_albedo;  // [shape][roughness][mu]
    std::vector<float> hyper_cauchy_average; // [shape][roughness]
    std::vector<float> dielectric_albedo;    // [side][ior][roughness][mu]
    std::vector<float> dielectric_average;   // [side][ior][roughness]
    std::vector<float> dielectric_fresnel;   // [ior]
};

EnergyTables compute_energy_tables(int strata, int threads);

// The single-source headers brdf/energy_table_ggx.h and brdf/energy_table_hyper_cauchy.h.
std::string ggx_table_header(const EnergyTables& tables, int strata);
std::string hyper_cauchy_table_header(const EnergyTables& tables, int strata);
std::string dielectric_table_header(const EnergyTables& tables, int strata);

}  // namespace lab::validation
