/* The fuzz layer's sheen: Estevez and Kulla 2017's "Charlie" distribution of fibre normals
 *   D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)
 * with Neubelt and Pettineo 2013's visibility V = 1 / (4 (mu_i + mu_o - mu_i mu_o)), f = D V.
 * Chosen over OpenPBR 1.1's LTC sheen (Zeltner, Burley and Chiang 2022) because it needs no fitted
 * coefficient table: its directional albedo, which the layering needs, is tabulated the way the
 * lab's other energy tables are (brdf/energy_table_openpbr.h). f depends on wo + wi and symmetric
 * terms only, so it is exactly reciprocal. Its directional albedo, though, passes 1 towards grazing
 * view at low roughness (3.7 at alpha 0.01, 1.4 at fuzz_roughness 0.3, measured), where V grows as
 * 1 / (mu_i + mu_o): the fuzz layer divides the lobe by max(1, E(mu_o)) (brdf/openpbr_model.h), so
 * the table holds E / SHEEN_TABLE_SCALE. Sampled cosine-weighted: the lobe is broad. alpha =
 * fuzz_roughness^2, at least SHEEN_MIN_ALPHA (below it the lobe hugs the horizon). */
#ifndef BRDF_SHEEN_H
#define BRDF_SHEEN_H
#include "single_source/vocabulary.h"
#include "warp.h"

#define SHEEN_MIN_ALPHA 0.01f
#define SHEEN_TABLE_SCALE 4.0f /* the sheen's albedo table holds E / 4: E stays below 3.7 */

SS_FN float sheen_alpha(float roughness) { return fmax(roughness * roughness, SHEEN_MIN_ALPHA); }

SS_FN float sheen_eval(float roughness, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float3 sum = wo + wi;
    float len2 = dot(sum, sum);
    if (!(len2 > 0.0f)) return 0.0f;
    float alpha = sheen_alpha(roughness);
    float sin2_h = fmax(1.0f - sum.z * sum.z / len2, 0.0f);
    float d = (2.0f + 1.0f / alpha) * pow(sin2_h, 0.5f / alpha) * (0.5f * SS_INV_PI);
    float v = 1.0f / (4.0f * (wi.z + wo.z - wi.z * wo.z));
    return d * v;
}

#endif
