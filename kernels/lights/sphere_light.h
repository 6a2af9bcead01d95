/* An emissive sphere as a light (centre c, radius r, radiance Le from both sides of its surface).
 *
 * From outside (|p - c| > r) only the cap facing p is visible: it subtends the cone of half-angle
 * theta_max, sin(theta_max) = r / |p - c|, and a direction is drawn uniformly in that cone
 * (pbrt-v4, Sphere::Sample), pdf = 1 / (2 pi (1 - cos theta_max)). 1 - cos is computed as
 * sin^2 / (1 + cos) and cos theta of the sample as 1 - u (1 - cos theta_max), which lose nothing to
 * cancellation however small the cap (pbrt switches to a series below 1.5 degrees; these forms are
 * exact at every size). The direction is built from (theta, phi) directly, so it has exactly the
 * density stated; the point on the sphere follows from the angle alpha at the centre.
 *
 * From inside (|p - c| <= r) every point of the surface is visible: a point is drawn uniformly by
 * area, pdf_A = 1 / (4 pi r^2), and converted to solid angle at p: pdf = pdf_A d^2 / |cos theta_l|,
 * theta_l between the sphere's normal and the direction at the sampled point.
 *
 * docs/lights.md derives the formulas; tests/test_light_sampling.cpp checks them by chi-square. */
#ifndef KERNELS_LIGHTS_SPHERE_LIGHT_H
#define KERNELS_LIGHTS_SPHERE_LIGHT_H
#include "single_source/vocabulary.h"
#include "brdf/frame.h"
#include "brdf/warp.h"
#include "kernels/lights/light.h"

/* A direction within this much (in sin of its angle to the axis) outside the cone still counts as
 * hitting the sphere: a unit vector built in float is only that exact, and a sample drawn at the
 * very edge must find the density it was drawn with. It widens the pdf's support, so the pdf
 * integrates to 1 + 2e-7 / sin(theta_max) (1.0008 at sin theta_max = 2.5e-4, 1/20 of the sun). */
#define SPHERE_LIGHT_EDGE_TOLERANCE 1e-7f

SS_FN float sphere_light_area_pdf(const Light* l) { return 1.0f / (4.0f * SS_PI * sqr(l->radius)); }

/* A point uniform on the surface by area (density sphere_light_area_pdf) and its outward normal. */
SS_FN float3 sphere_light_sample_area(const Light* l, float2 u, float3* normal) {
    float3 n = square_to_uniform_sphere(u.x, u.y);
    *normal = n;
    return float3_from_array(l->position) + n * l->radius;
}

/* 1 - cos(theta_max) for sin^2(theta_max) = r^2 / d^2 < 1, without cancellation. */
SS_FN float sphere_light_cone_one_minus_cos(float sin2_max) { return sin2_max / (1.0f + safe_sqrt(1.0f - sin2_max)); }

SS_FN LightSample sphere_light_sample(const Light* l, float3 p, float2 u) {
    float3 c = float3_from_array(l->position);
    float r = l->radius;
    float3 to_center = c - p;
    float d2 = dot(to_center, to_center);
    LightSample s = light_sample_none();
    s.radiance = float3_from_array(l->emission);
    if (d2 <= r * r) { /* inside: area sampling, converted to solid angle */
        float3 n;
        float3 q = sphere_light_sample_area(l, u, &n);
        float3 v = q - p;
        float dist = length(v);
        if (!(dist > 0.0f)) return light_sample_none();
        float3 wi = v / dist;
        float cos_l = fabs(dot(n, wi));
        if (!(cos_l > 0.0f)) return light_sample_none();
        s.wi = wi;
        s.distance = dist;
        s.pdf = sphere_light_area_pdf(l) * dist * dist / cos_l;
        s.position = q;
        s.normal = n;
        return s;
    }
    /* outside: uniform in the cone of the visible cap, axis z from p towards the centre */
    float d = sqrt(d2);
    float sin2_max = r * r / d2;
    float one_minus_cos_max = sphere_light_cone_one_minus_cos(sin2_max);
    if (!(one_minus_cos_max > 0.0f)) return light_sample_none(); /* too small to be seen in float */
    float one_minus_cos = u.x * one_minus_cos_max;
    float cos_theta = 1.0f - one_minus_cos;
    float sin2_theta = one_minus_cos * (2.0f - one_minus_cos);
    float sin_theta = safe_sqrt(sin2_theta);
    float phi = 2.0f * SS_PI * u.y;
    ShadingFrame frame = frame_from_normal(to_center / d);
    float3 wi = frame_to_world(frame, make_float3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta));
    /* the nearer intersection of the ray with the sphere, seen from the centre: the angle alpha
     * from the axis back towards p. In the triangle (p, centre, point) the angle at the point is
     * beta, obtuse, sin beta = sin theta / sin_max, and alpha = pi - theta - beta, so
     *   cos alpha = sin^2 theta / sin_max + cos theta sqrt(1 - sin^2 theta / sin^2_max)  (pbrt),
     *   sin alpha = sin theta (cos theta / sin_max - sqrt(1 - sin^2 theta / sin^2_max));
     * sin alpha from its own formula, not from 1 - cos^2, which loses it for small alpha. */
    float sin_max = r / d;
    float cos_beta = safe_sqrt(1.0f - sin2_theta / sin2_max);
    float cos_alpha = sin2_theta / sin_max + cos_theta * cos_beta;
    float sin_alpha = fmax(sin_theta * (cos_theta / sin_max - cos_beta), 0.0f);
    float3 n = frame_to_world(frame, make_float3(sin_alpha * cos(phi), sin_alpha * sin(phi), -cos_alpha));
    s.position = c + n * r;
    s.normal = n;
    s.wi = normalize(wi);
    s.distance = length(s.position - p);
    s.pdf = 1.0f / (2.0f * SS_PI * one_minus_cos_max);
    return s;
}

/* The solid-angle density with which sphere_light_sample() from p returns the unit direction wi;
 * 0 when the ray from p along wi misses the sphere. */
SS_FN float sphere_light_pdf(const Light* l, float3 p, float3 wi) {
    float3 c = float3_from_array(l->position);
    float r = l->radius;
    float3 o = p - c;
    float d2 = dot(o, o);
    if (d2 <= r * r) {
        /* inside: the ray leaves through the exit point at t > 0 of |o + t wi|^2 = r^2; with
         * b = o.wi and k = |o|^2 - r^2 <= 0, t = -b + sqrt(b^2 - k) (written as -k / (b + sqrt)
         * for b > 0, no cancellation), and cos theta_l at the exit point = sqrt(b^2 - k) / r */
        float b = dot(o, wi);
        float k = d2 - r * r;
        float root = sqrt(b * b - k);
        if (!(root > 0.0f)) return 0.0f;
        float t = b > 0.0f ? -k / (b + root) : root - b;
        return t * t / (4.0f * SS_PI * r * root);
    }
    float sin2_max = r * r / d2;
    /* hit test in the cone: sin of the angle between wi and the axis, from the cross product */
    if (!(dot(wi, o) < 0.0f)) return 0.0f;
    float3 x = cross(wi, o);
    float sin_angle = sqrt(dot(x, x) / d2);
    if (sin_angle > sqrt(sin2_max) + SPHERE_LIGHT_EDGE_TOLERANCE) return 0.0f;
    float one_minus_cos_max = sphere_light_cone_one_minus_cos(sin2_max);
    if (!(one_minus_cos_max > 0.0f)) return 0.0f;
    return 1.0f / (2.0f * SS_PI * one_minus_cos_max);
}

#endif
