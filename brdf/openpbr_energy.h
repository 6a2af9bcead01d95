/* The directional albedos OpenPBR's layering passes energy down with (brdf/openpbr_model.h): what a
 * dielectric interface (the coat, the dielectric specular) or the fuzz reflects at mu, looked up in
 * brdf/energy_table_openpbr.h (written by tools/generate_energy_tables). Stored values are rounded up,
 * so what a layer passes down, 1 - E, never exceeds what it lets through. */
#ifndef BRDF_OPENPBR_ENERGY_H
#define BRDF_OPENPBR_ENERGY_H
#include "single_source/vocabulary.h"
#include "energy_grid.h"
#include "energy_table_openpbr.h"
#include "fresnel.h"
#include "microfacet.h"
#include "sheen.h"

/* E(mu) of GGX reflection off a dielectric of index eta; a smooth interface's is its Fresnel reflectance. */
SS_FN float openpbr_specular_albedo(Microfacet mf, float eta, float mu) {
    if (microfacet_is_smooth(mf)) return fresnel_dielectric(clamp(mu, 0.0f, 1.0f), eta);
    return energy_grid_ior_albedo(energy_openpbr_specular_albedo, sqrt(sqrt(mf.ax * mf.ay)), eta, mu);
}

/* Its cosine-weighted average E_avg; a smooth interface's from the table's smooth row. */
SS_FN float openpbr_specular_average(Microfacet mf, float eta) {
    return energy_grid_ior_average(energy_openpbr_specular_average, microfacet_is_smooth(mf) ? 0.0f : sqrt(sqrt(mf.ax * mf.ay)), eta);
}

/* E(mu) of the unnormalised sheen lobe (may pass 1, brdf/sheen.h). */
SS_FN float openpbr_sheen_albedo(float roughness, float mu) {
    return SHEEN_TABLE_SCALE * energy_table_albedo(energy_openpbr_sheen_albedo, roughness, mu);
}

#endif
