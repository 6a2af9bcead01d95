/* MERL's measured-BRDF table (Matusik et al. 2003, "A Data-Driven Reflectance Model"): isotropic
 * BRDFs tabulated over Rusinkiewicz's half/difference angles (theta_h, theta_d, phi_d), 90 x 90 x 180
 * bins. theta_h bins are spaced as sqrt(theta_h) to resolve highlights; phi_d covers [0, pi) only,
 * since isotropy and reciprocity make the BRDF periodic in phi_d with period pi. That periodicity
 * makes any lookup in this parameterisation reciprocal: swapping wo and wi keeps the half vector
 * and theta_d and moves phi_d by pi.
 *
 * The table in memory is interleaved RGB floats in physical units (1/sr), entry e at 3e, 3e+1, 3e+2;
 * the file format (channel blocks of scaled doubles) is brdf/host/merl_file.hpp's business. */
#ifndef BRDF_MERL_H
#define BRDF_MERL_H
#include "single_source/vocabulary.h"

#define MERL_THETA_H_BINS 90
#define MERL_THETA_D_BINS 90
#define MERL_PHI_D_BINS 180
#define MERL_ENTRY_COUNT (MERL_THETA_H_BINS * MERL_THETA_D_BINS * MERL_PHI_D_BINS)

/* Rusinkiewicz's half/difference angles of a pair of directions in the local frame (z = normal).
 * Angles come from atan2, not acos: acos loses the small theta_h near the highlight, where the
 * sqrt spacing puts the finest bins. */
typedef struct HalfDiffAngles { float theta_h, theta_d, phi_d; } HalfDiffAngles;

SS_FN HalfDiffAngles half_diff_from_directions(float3 wo, float3 wi) {
    float3 h = normalize(wo + wi);
    float theta_h = atan2(sqrt(h.x * h.x + h.y * h.y), h.z);
    float phi_h = atan2(h.y, h.x);
    /* d = wi rotated by -phi_h about the normal, then by -theta_h about the binormal (y). */
    float cp = cos(phi_h), sp = sin(phi_h);
    float3 t = make_float3(cp * wi.x + sp * wi.y, -sp * wi.x + cp * wi.y, wi.z);
    float ct = cos(theta_h), st = sin(theta_h);
    float3 d = make_float3(ct * t.x - st * t.z, t.y, st * t.x + ct * t.z);
    HalfDiffAngles a;
    a.theta_h = theta_h;
    a.theta_d = atan2(sqrt(d.x * d.x + d.y * d.y), d.z);
    a.phi_d = atan2(d.y, d.x);
    return a;
}

/* The inverse, with phi_h = 0 (isotropy): the pair (wo, wi) whose half/difference angles are a. */
SS_FN void directions_from_half_diff(HalfDiffAngles a, float3* wo, float3* wi) {
    float3 d = make_float3(sin(a.theta_d) * cos(a.phi_d), sin(a.theta_d) * sin(a.phi_d), cos(a.theta_d));
    float ct = cos(a.theta_h), st = sin(a.theta_h);
    float3 in = make_float3(ct * d.x + st * d.z, d.y, -st * d.x + ct * d.z); /* +theta_h about y */
    float3 h = make_float3(st, 0.0f, ct);
    *wi = in;
    *wo = 2.0f * dot(in, h) * h - in;
}

/* Continuous bin coordinates: bin i covers [i, i + 1), its entry is the value at the centre i + 0.5. */
SS_FN float merl_theta_h_coordinate(float theta_h) {
    return (float)MERL_THETA_H_BINS * sqrt(fmax(theta_h, 0.0f) / (0.5f * SS_PI));
}
SS_FN float merl_theta_d_coordinate(float theta_d) {
    return (float)MERL_THETA_D_BINS * fmax(theta_d, 0.0f) / (0.5f * SS_PI);
}
SS_FN float merl_phi_d_coordinate(float phi_d) {
    float p = fmod(phi_d, SS_PI);
    if (p < 0.0f) p += SS_PI;
    return (float)MERL_PHI_D_BINS * p / SS_PI;
}

/* The angles at the centre of bin (ih, id, ip): where the table's entry holds exactly. */
SS_FN HalfDiffAngles merl_bin_center(int ih, int id, int ip) {
    float uh = ((float)ih + 0.5f) / (float)MERL_THETA_H_BINS;
    HalfDiffAngles a;
    a.theta_h = 0.5f * SS_PI * uh * uh;
    a.theta_d = 0.5f * SS_PI * ((float)id + 0.5f) / (float)MERL_THETA_D_BINS;
    a.phi_d = SS_PI * ((float)ip + 0.5f) / (float)MERL_PHI_D_BINS;
    return a;
}

SS_FN int merl_entry_index(int ih, int id, int ip) {
    return (ih * MERL_THETA_D_BINS + id) * MERL_PHI_D_BINS + ip;
}

/* Linear interpolation weights between the bin centres around coordinate u; clamped at the ends. */
SS_FN void merl_clamped_cell(float u, int bins, int* i0, int* i1, float* t) {
    float x = clamp(u - 0.5f, 0.0f, (float)(bins - 1));
    int i = min((int)x, bins - 2);
    *i0 = i;
    *i1 = i + 1;
    *t = x - (float)i;
}
/* phi_d wraps around (period pi), so its cell between the last and the first bin is a real cell. */
SS_FN void merl_periodic_cell(float u, int bins, int* i0, int* i1, float* t) {
    float x = u - 0.5f;
    float f = floor(x);
    int i = (int)f;
    *t = x - f;
    *i0 = (i + bins) % bins;
    *i1 = (i + 1 + bins) % bins;
}

SS_FN float3 merl_entry(GLOBAL_MEM const float* table, int e) {
    return make_float3(table[3 * e], table[3 * e + 1], table[3 * e + 2]);
}

/* The tabulated BRDF at the angles a, trilinear between bin centres in (sqrt theta_h, theta_d, phi_d).
 * Non-negative whenever the table is (the reader rejects negative entries). */
SS_FN float3 merl_lookup(GLOBAL_MEM const float* table, HalfDiffAngles a) {
    int h0, h1, d0, d1, p0, p1;
    float th, td, tp;
    merl_clamped_cell(merl_theta_h_coordinate(a.theta_h), MERL_THETA_H_BINS, &h0, &h1, &th);
    merl_clamped_cell(merl_theta_d_coordinate(a.theta_d), MERL_THETA_D_BINS, &d0, &d1, &td);
    merl_periodic_cell(merl_phi_d_coordinate(a.phi_d), MERL_PHI_D_BINS, &p0, &p1, &tp);
    float3 c00 = mix(merl_entry(table, merl_entry_index(h0, d0, p0)), merl_entry(table, merl_entry_index(h0, d0, p1)), tp);
    float3 c01 = mix(merl_entry(table, merl_entry_index(h0, d1, p0)), merl_entry(table, merl_entry_index(h0, d1, p1)), tp);
    float3 c10 = mix(merl_entry(table, merl_entry_index(h1, d0, p0)), merl_entry(table, merl_entry_index(h1, d0, p1)), tp);
    float3 c11 = mix(merl_entry(table, merl_entry_index(h1, d1, p0)), merl_entry(table, merl_entry_index(h1, d1, p1)), tp);
    return mix(mix(c00, c01, td), mix(c10, c11, td), th);
}

/* The measured BRDF f(wo, wi) in the local frame; zero unless both directions are above the surface. */
SS_FN float3 merl_eval(GLOBAL_MEM const float* table, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return float3_splat(0.0f);
    return merl_lookup(table, half_diff_from_directions(wo, wi));
}

#endif
