/* Rect and disk emitters as lights: flat, one-sided (they emit towards n = U x V / |U x V| only),
 * radiance Le on that side (docs/lights.md).
 *
 * Rect (the parallelogram c + x U + y V, |x|, |y| <= 1/2): where its edges are perpendicular and
 * the rectangle subtends a solid angle S in [RECT_LIGHT_MIN_SOLID_ANGLE, RECT_LIGHT_MAX_SOLID_ANGLE]
 * from p, a direction is drawn uniformly in that spherical rectangle (Urena, Fajardo and King 2013,
 * "An Area-Preserving Parametrization for Spherical Rectangles"), pdf = 1 / S. Elsewhere (a
 * parallelogram that is no rectangle, a rectangle too small or too near in angle for float) a point
 * is drawn uniformly by area and converted to solid angle, pdf = d^2 / (A cos theta_l).
 * Disk (c + x U + y V, x^2 + y^2 <= 1, U and V perpendicular of length r): a point uniform by area
 * (Shirley-Chiu's concentric map), converted alike.
 *
 * Both samplers decide from p alone which density they use, so area_light_pdf() from p finds the
 * same one. tests/test_light_sampling.cpp checks them by chi-square. */
#ifndef KERNELS_LIGHTS_AREA_LIGHT_H
#define KERNELS_LIGHTS_AREA_LIGHT_H
#include "single_source/vocabulary.h"
#include "brdf/warp.h"
#include "kernels/lights/light.h"

/* pbrt-v4's bounds (lights.cpp, DiffuseAreaLight): below about 3e-4 sr the four angles' sum loses
 * the spherical rectangle's area to float rounding, above about 6.22 sr (a point almost on the
 * rectangle) its warp is unstable; area sampling is exact at both. */
#define RECT_LIGHT_MIN_SOLID_ANGLE 3e-4f
#define RECT_LIGHT_MAX_SOLID_ANGLE 6.22f

SS_FN float3 area_light_center(const Light* l) { return float3_from_array(l->position); }
SS_FN float3 area_light_u(const Light* l) { return float3_from_array(l->edge_u); }
SS_FN float3 area_light_v(const Light* l) { return float3_from_array(l->edge_v); }

/* The unit normal of the emitting side, U x V / |U x V|. */
SS_FN float3 area_light_normal(const Light* l) { return normalize(cross(area_light_u(l), area_light_v(l))); }

/* |U x V| for a rect, pi r^2 for a disk (|U x V| = r^2). */
SS_FN float area_light_area(const Light* l) {
    float a = length(cross(area_light_u(l), area_light_v(l)));
    return l->type == LIGHT_DISK ? SS_PI * a : a;
}

SS_FN float area_light_area_pdf(const Light* l) { return 1.0f / area_light_area(l); }

/* The light's point for st in [0, 1]^2: a rect's c + (s - 1/2) U + (t - 1/2) V, so that st = (0, 0)
 * is its corner c - U/2 - V/2 and s runs along U, t along V; a disk's through Shirley-Chiu's
 * concentric map, which keeps areas (every part of the square maps onto pi r^2 times its area). */
SS_FN float3 area_light_point(const Light* l, float2 st) {
    float2 xy = l->type == LIGHT_DISK ? square_to_concentric_disk(st.x, st.y) : make_float2(st.x - 0.5f, st.y - 0.5f);
    return area_light_center(l) + area_light_u(l) * xy.x + area_light_v(l) * xy.y;
}

/* A point uniform by area (density area_light_area_pdf) and the normal of its emitting side. */
SS_FN float3 area_light_sample_area(const Light* l, float2 u, float3* normal) {
    *normal = area_light_normal(l);
    return area_light_point(l, u);
}

/* A point this much (in its coordinates along U and V) outside the light still counts as on it: a
 * sample drawn at the very edge, found again along its float direction, must find the density it was
 * drawn with. It widens the density's support by a relative 1e-5 of the light's size, so the pdf
 * integrates to at most 1 + 4e-5. */
#define AREA_LIGHT_EDGE_TOLERANCE 1e-5f

/* The coordinates x, y along U and V of the point q of the light's plane (from the dual vectors
 * V x N / |N|^2 and N x U / |N|^2, N = U x V), and whether q lies on the light: x, y within the rect
 * or the unit disk. */
SS_FN float2 area_light_coordinates(const Light* l, float3 q) {
    float3 u = area_light_u(l), v = area_light_v(l);
    float3 n = cross(u, v);
    float3 d = q - area_light_center(l);
    float inv = 1.0f / dot(n, n);
    return make_float2(dot(d, cross(v, n)) * inv, dot(d, cross(n, u)) * inv);
}

SS_FN bool area_light_contains(const Light* l, float3 q) {
    float2 xy = area_light_coordinates(l, q);
    float x = xy.x, y = xy.y;
    const float reach = 1.0f + AREA_LIGHT_EDGE_TOLERANCE;
    return l->type == LIGHT_DISK ? x * x + y * y <= reach * reach : fabs(x) <= 0.5f * reach && fabs(y) <= 0.5f * reach;
}

/* The spherical rectangle the rect subtends from p, in the rect's frame (Urena et al. 2013, §3):
 * ex, ey along U and V, ez = ex x ey; the corner c - U/2 - V/2 at (x0, y0, z0) from p, z0 < 0 for p
 * on the emitting side. */
typedef struct SphericalRect {
    float3 ex, ey, ez;
    float x0, y0, z0, x1, y1;
    float b0, b1, k, solid_angle;
} SphericalRect;

/* Whether the rect's edges are perpendicular (to float precision of its cosine), so that the
 * spherical-rectangle sampler applies. */
SS_FN bool rect_light_is_rectangle(const Light* l) {
    float3 u = area_light_u(l), v = area_light_v(l);
    return fabs(dot(u, v)) <= 1e-6f * length(u) * length(v);
}

SS_FN SphericalRect spherical_rect_make(const Light* l, float3 p) {
    SphericalRect r;
    float3 u = area_light_u(l), v = area_light_v(l);
    float lu = length(u), lv = length(v);
    r.ex = u / lu;
    r.ey = v / lv;
    r.ez = cross(r.ex, r.ey);
    float3 d = area_light_center(l) - (u + v) * 0.5f - p;
    r.x0 = dot(d, r.ex);
    r.y0 = dot(d, r.ey);
    r.z0 = dot(d, r.ez);
    r.x1 = r.x0 + lu;
    r.y1 = r.y0 + lv;
    /* the normals of the four planes through p and an edge, and the interior angles between them */
    float z2 = r.z0 * r.z0;
    float3 n0 = make_float3(0.0f, r.z0, -r.y0) / sqrt(z2 + r.y0 * r.y0);
    float3 n1 = make_float3(-r.z0, 0.0f, r.x1) / sqrt(z2 + r.x1 * r.x1);
    float3 n2 = make_float3(0.0f, -r.z0, r.y1) / sqrt(z2 + r.y1 * r.y1);
    float3 n3 = make_float3(r.z0, 0.0f, -r.x0) / sqrt(z2 + r.x0 * r.x0);
    float g0 = acos(clamp(-dot(n0, n1), -1.0f, 1.0f));
    float g1 = acos(clamp(-dot(n1, n2), -1.0f, 1.0f));
    float g2 = acos(clamp(-dot(n2, n3), -1.0f, 1.0f));
    float g3 = acos(clamp(-dot(n3, n0), -1.0f, 1.0f));
    r.b0 = n0.z;
    r.b1 = n2.z;
    r.k = 2.0f * SS_PI - g2 - g3;
    r.solid_angle = g0 + g1 - r.k;
    return r;
}

/* Whether p sees the rect by solid angle: a rectangle, p on its emitting side, S within bounds. */
SS_FN bool rect_light_uses_solid_angle(const Light* l, const SphericalRect* r) {
    return l->type == LIGHT_RECT && r->z0 < 0.0f && r->solid_angle >= RECT_LIGHT_MIN_SOLID_ANGLE && r->solid_angle <= RECT_LIGHT_MAX_SOLID_ANGLE;
}

/* The point of the spherical rectangle for u (Urena et al. 2013, algorithm 1), uniform in solid
 * angle seen from p. */
SS_FN float3 spherical_rect_sample(const SphericalRect* r, float3 p, float2 u) {
    float au = u.x * r->solid_angle + r->k;
    float fu = (cos(au) * r->b0 - r->b1) / sin(au);
    float cu = clamp((fu > 0.0f ? 1.0f : -1.0f) / sqrt(fu * fu + r->b0 * r->b0), -1.0f, 1.0f);
    float xu = clamp(-(cu * r->z0) / safe_sqrt(1.0f - cu * cu), r->x0, r->x1); /* an infinity clamps to the edge */
    float d = sqrt(xu * xu + r->z0 * r->z0);
    float h0 = r->y0 / sqrt(d * d + r->y0 * r->y0);
    float h1 = r->y1 / sqrt(d * d + r->y1 * r->y1);
    float hv = h0 + u.y * (h1 - h0);
    float hv2 = hv * hv;
    float yv = hv2 < 1.0f - 1e-6f ? hv * d / sqrt(1.0f - hv2) : r->y1;
    return p + r->ex * xu + r->ey * clamp(yv, r->y0, r->y1) + r->ez * r->z0;
}

/* The sample's geometry for the light's point q (emitting side's normal n) seen from p: wi,
 * distance, position and normal into *s, the cosine at q between n and -wi into *cos_l; false when q
 * is p or p does not see its emitting side. */
SS_FN bool area_light_sample_point(float3 p, float3 q, float3 n, LightSample* s, float* cos_l) {
    float3 w = q - p;
    float dist = length(w);
    if (!(dist > 0.0f)) return false;
    float3 wi = w / dist;
    *cos_l = -dot(n, wi);
    if (!(*cos_l > 0.0f)) return false;
    s->wi = wi;
    s->distance = dist;
    s->position = q;
    s->normal = n;
    return true;
}

SS_FN LightSample area_light_sample(const Light* l, float3 p, float2 u) {
    float3 n = area_light_normal(l);
    if (!(dot(p - area_light_center(l), n) > 0.0f)) return light_sample_none(); /* behind it: it emits nothing here */
    LightSample s = light_sample_none();
    float pdf_solid = 0.0f;
    SphericalRect r;
    if (l->type == LIGHT_RECT && rect_light_is_rectangle(l)) {
        r = spherical_rect_make(l, p);
        if (rect_light_uses_solid_angle(l, &r)) pdf_solid = 1.0f / r.solid_angle;
    }
    float3 q = pdf_solid > 0.0f ? spherical_rect_sample(&r, p, u) : area_light_sample_area(l, u, &n);
    float cos_l;
    if (!area_light_sample_point(p, q, n, &s, &cos_l)) return light_sample_none();
    s.radiance = float3_from_array(l->emission);
    s.pdf = pdf_solid > 0.0f ? pdf_solid : s.distance * s.distance / (area_light_area(l) * cos_l);
    return s;
}

/* Whether the ray from p along the unit direction wi meets the light's emitting side: then its
 * distance *t and the cosine *cos_l there between -wi and the light's normal. */
SS_FN bool area_light_ray_hit(const Light* l, float3 p, float3 wi, float* t, float* cos_l) {
    float3 n = area_light_normal(l);
    *cos_l = -dot(n, wi);
    float height = dot(p - area_light_center(l), n);
    if (!(*cos_l > 0.0f) || !(height > 0.0f)) return false;
    *t = height / *cos_l;
    return area_light_contains(l, p + wi * *t);
}

/* The solid-angle density with which area_light_sample() from p returns the unit direction wi; 0
 * when the ray misses the light or meets its back. */
SS_FN float area_light_pdf(const Light* l, float3 p, float3 wi) {
    float t, cos_l;
    if (!area_light_ray_hit(l, p, wi, &t, &cos_l)) return 0.0f;
    if (l->type == LIGHT_RECT && rect_light_is_rectangle(l)) {
        SphericalRect r = spherical_rect_make(l, p);
        if (rect_light_uses_solid_angle(l, &r)) return 1.0f / r.solid_angle;
    }
    return t * t / (area_light_area(l) * cos_l);
}

/* The radiance the light sends from its point q along the unit direction w: Le on its emitting
 * side, 0 behind it. */
SS_FN float3 area_light_radiance(const Light* l, float3 w) {
    return dot(area_light_normal(l), w) > 0.0f ? float3_from_array(l->emission) : float3_splat(0.0f);
}

#endif
