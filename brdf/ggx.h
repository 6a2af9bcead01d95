/* Anisotropic GGX / Trowbridge-Reitz distribution of normals (Walter et al. 2007; Heitz 2014),
 * with its Smith Lambda and visible-normal sampling (Heitz 2018). Directions in the local frame. */
#ifndef BRDF_GGX_H
#define BRDF_GGX_H
#include "single_source/vocabulary.h"

/* D(m) = 1 / (pi ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2), written in m. */
SS_FN float ggx_d(float3 m, float ax, float ay) {
    if (m.z <= 0.0f) return 0.0f;
    float e = sqr(m.x / ax) + sqr(m.y / ay) + m.z * m.z;
    return 1.0f / (SS_PI * ax * ay * e * e);
}

/* Lambda(w) = (-1 + sqrt(1 + alpha(phi)^2 tan^2 theta)) / 2 (Heitz 2014, eq. 86). */
SS_FN float ggx_lambda(float3 w, float ax, float ay) {
    float c2 = w.z * w.z;
    if (c2 <= 0.0f) return 1e30f;
    float alpha2_tan2 = (sqr(ax * w.x) + sqr(ay * w.y)) / c2;
    /* (-1 + sqrt(1 + a)) / 2 rewritten as a / (2 (1 + sqrt(1 + a))): no cancellation when a is small */
    return 0.5f * alpha2_tan2 / (1.0f + sqrt(1.0f + alpha2_tan2));
}

/* Visible normals of w (flipped to the upper side): Heitz 2018, "Sampling the GGX distribution
 * of visible normals". pdf(m) = G1(w) max(0, w.m) D(m) / |cos theta_w|. */
SS_FN float3 ggx_sample_visible_normal(float3 w, float ax, float ay, float u1, float u2) {
    float3 wh = normalize(make_float3(ax * w.x, ay * w.y, w.z));
    if (wh.z < 0.0f) wh = -wh;
    float len2 = wh.x * wh.x + wh.y * wh.y;
    float3 t1 = len2 > 0.0f ? make_float3(-wh.y, wh.x, 0.0f) / sqrt(len2) : make_float3(1.0f, 0.0f, 0.0f);
    float3 t2 = cross(wh, t1);
    float r = sqrt(u1); /* and the angle 2 pi u2, through cospi and sinpi (brdf/warp.h says why) */
    float p1 = r * cospi(2.0f * u2), p2 = r * sinpi(2.0f * u2);
    float s = 0.5f * (1.0f + wh.z);
    p2 = (1.0f - s) * safe_sqrt(1.0f - p1 * p1) + s * p2;
    float3 nh = p1 * t1 + p2 * t2 + safe_sqrt(1.0f - p1 * p1 - p2 * p2) * wh;
    return normalize(make_float3(ax * nh.x, ay * nh.y, fmax(1e-7f, nh.z)));
}

#endif
