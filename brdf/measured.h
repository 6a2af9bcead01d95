/* A measured material: a MERL table (brdf/merl.h) and its tabulated importance sampler, one block of
 * floats in the measured-tables buffer (on the host brdf/host/measured_registry.hpp, in a kernel an
 * OpenCL buffer argument), starting at the material's measured_offset:
 *   [MEASURED_TABLE_FLOATS]  the MERL table, interleaved RGB in 1/sr
 *   [MEASURED_THETA_O_BINS x MEASURED_SAMPLER_BIN_FLOATS]  the sampler, one 2D distribution per
 *       bin of the outgoing (given) direction's polar angle.
 * Each sampler bin is a piecewise-constant density over the incident hemisphere in (theta_i, |phi_i -
 * phi_o|): MEASURED_THETA_I_BINS bands uniform in theta_i, MEASURED_PHI_BINS cells over the relative
 * azimuth [0, pi] (an isotropic BRDF is symmetric in its sign, which is drawn with even odds). Within a
 * cell the density is uniform in solid angle. A bin holds the marginal CDF over the bands (THETA_I_BINS
 * + 1 floats) and, per band, the conditional CDF over its cells (PHI_BINS + 1 floats). The sampler and
 * the pdf read the same bin and the same cells, so the pdf is exact for the samples whatever the
 * tables' resolution: the resolution only decides how close the density follows f cos. How the host
 * builds the CDFs, and what they cost: docs/materials.md, Measured materials. */
#ifndef BRDF_MEASURED_H
#define BRDF_MEASURED_H
#include "bsdf_sample.h"
#include "merl.h"
#include "single_source/vocabulary.h"

#define MEASURED_THETA_O_BINS 32
#define MEASURED_THETA_I_BINS 64
#define MEASURED_PHI_BINS 64
#define MEASURED_TABLE_FLOATS (3 * MERL_ENTRY_COUNT)
#define MEASURED_SAMPLER_BIN_FLOATS ((MEASURED_THETA_I_BINS + 1) + MEASURED_THETA_I_BINS * (MEASURED_PHI_BINS + 1))
#define MEASURED_BLOCK_FLOATS (MEASURED_TABLE_FLOATS + MEASURED_THETA_O_BINS * MEASURED_SAMPLER_BIN_FLOATS)

SS_FN float measured_polar_angle(float3 w) { return atan2(sqrt(w.x * w.x + w.y * w.y), w.z); }

/* The bin of a polar angle in [0, pi/2] cut into `bins` equal bands. */
SS_FN int measured_polar_bin(float theta, int bins) {
    int i = (int)(theta * (2.0f / SS_PI) * (float)bins);
    return clamp(i, 0, bins - 1);
}

/* wo's azimuth direction in the tangent plane; along the normal, where it has none, the tangent. The
 * sampler and the pdf both measure azimuths from it. */
SS_FN float2 measured_azimuth_axis(float3 wo) {
    float r = sqrt(wo.x * wo.x + wo.y * wo.y);
    if (!(r > 0.0f)) return make_float2(1.0f, 0.0f);
    return make_float2(wo.x / r, wo.y / r);
}

SS_FN GLOBAL_MEM const float* measured_sampler_bin(GLOBAL_MEM const float* block, float3 wo) {
    int k = measured_polar_bin(measured_polar_angle(wo), MEASURED_THETA_O_BINS);
    return block + MEASURED_TABLE_FLOATS + k * MEASURED_SAMPLER_BIN_FLOATS;
}

/* The cell i of a CDF of n cells (cdf[0] = 0, cdf[n] = 1) with cdf[i] <= u < cdf[i + 1]: never an
 * empty cell for u in [0, 1). */
SS_FN int measured_cdf_find(GLOBAL_MEM const float* cdf, int n, float u) {
    int lo = 0, hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* The solid angle of one cell of band j (half of it: the azimuth cells cover [0, pi] only). */
SS_FN float measured_cell_solid_angle(int j) {
    /* cos a - cos b as 2 sin((a + b) / 2) sin((b - a) / 2): no cancellation, so the OpenCL and C++
     * builds (whose cos differ in the last bit) agree on it to a few ulps */
    float band = 0.5f * SS_PI / (float)MEASURED_THETA_I_BINS;
    return 2.0f * sin(((float)j + 0.5f) * band) * sin(0.5f * band) * (SS_PI / (float)MEASURED_PHI_BINS);
}

SS_FN float measured_pdf(GLOBAL_MEM const float* block, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    GLOBAL_MEM const float* bin = measured_sampler_bin(block, wo);
    int j = measured_polar_bin(measured_polar_angle(wi), MEASURED_THETA_I_BINS);
    float2 a = measured_azimuth_axis(wo);
    float across = fabs(a.x * wi.y - a.y * wi.x), along = a.x * wi.x + a.y * wi.y;
    /* at the pole both are zero, maybe negative zero, whose atan2 is pi: the pole is azimuth 0 */
    float dphi = across == 0.0f && along == 0.0f ? 0.0f : atan2(across, along);
    int l = clamp((int)(dphi * ((float)MEASURED_PHI_BINS / SS_PI)), 0, MEASURED_PHI_BINS - 1);
    GLOBAL_MEM const float* row = bin + (MEASURED_THETA_I_BINS + 1) + j * (MEASURED_PHI_BINS + 1);
    float p = (bin[j + 1] - bin[j]) * (row[l + 1] - row[l]);
    return p / (2.0f * measured_cell_solid_angle(j));
}

/* u: three uniform numbers in [0, 1): u.x picks the band and the polar angle inside it, u.y the cell
 * and the azimuth inside it, u.z the azimuth's sign. */
SS_FN BsdfSample measured_sample(GLOBAL_MEM const float* block, float3 wo, float3 u) {
    BsdfSample s = bsdf_sample_failed();
    if (!(wo.z > 0.0f)) return s;
    GLOBAL_MEM const float* bin = measured_sampler_bin(block, wo);
    float ux = fmin(u.x, 0.99999994f), uy = fmin(u.y, 0.99999994f);
    int j = measured_cdf_find(bin, MEASURED_THETA_I_BINS, ux);
    float tj = clamp((ux - bin[j]) / (bin[j + 1] - bin[j]), 0.0f, 1.0f);
    GLOBAL_MEM const float* row = bin + (MEASURED_THETA_I_BINS + 1) + j * (MEASURED_PHI_BINS + 1);
    int l = measured_cdf_find(row, MEASURED_PHI_BINS, uy);
    float tl = clamp((uy - row[l]) / (row[l + 1] - row[l]), 0.0f, 1.0f);
    float band = 0.5f * SS_PI / (float)MEASURED_THETA_I_BINS;
    /* uniform in solid angle inside the cell: linear in cos theta */
    float cos_theta = mix(cos((float)j * band), cos((float)(j + 1) * band), tj);
    float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    float dphi = ((float)l + tl) * (SS_PI / (float)MEASURED_PHI_BINS);
    if (u.z < 0.5f) dphi = -dphi;
    float2 a = measured_azimuth_axis(wo);
    float c = cos(dphi), sn = sin(dphi);
    float3 wi = make_float3(sin_theta * (a.x * c - a.y * sn), sin_theta * (a.y * c + a.x * sn), cos_theta);
    s.pdf = measured_pdf(block, wo, wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_failed();
    s.wi = wi;
    s.f = merl_eval(block, wo, wi);
    s.flags = BSDF_REFLECTION;
    return s;
}

#endif
