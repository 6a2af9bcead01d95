/* Capped cone around the y axis: base disk of radius r in the plane y = 0, centred at the origin,
 * apex at (0, height, 0) (r > 0, height > 0). */
#ifndef SDF_PRIMITIVES_CONE_H
#define SDF_PRIMITIVES_CONE_H

#include "single_source/vocabulary.h"
#include "sdf/primitives/radial.h"

/* The cone's meridian section, in the half-plane (rho = |p.xz|, y): the triangle with vertices
 * (0, 0), (r, 0), (0, height). Its edge on the axis is interior to the solid of revolution, so the
 * boundary that matters is the base segment (0,0)-(r,0) and the slant segment (r,0)-(0,height).
 * (For rho >= 0, a point's nearest point on the full section, mirrored about the axis, is always on
 * this half.) ConeFeatures holds the offsets from the nearest point of each segment to (rho, y). */
typedef struct ConeFeatures {
    SDF_FLOAT base_rho, base_y;   /* (rho, y) minus its nearest point on the base segment */
    SDF_FLOAT slant_rho, slant_y; /* (rho, y) minus its nearest point on the slant segment */
    SDF_FLOAT slant_t;            /* where that point lies on the slant: 0 at the rim, 1 at the apex */
    SDF_MASK inside;              /* non-0 when (rho, y) is in the closed triangle */
} ConeFeatures;

SS_FN ConeFeatures cone_features(SDF_FLOAT rho, SDF_FLOAT y, float r, float height) {
    ConeFeatures c;
    c.base_rho = fmax(rho - r, 0.0f);
    c.base_y = y;
    /* e = (-r, height): rim -> apex; w = (rho - r, y): rim -> point; t = w.e / e.e */
    SDF_FLOAT w_rho = rho - r;
    c.slant_t = clamp((-w_rho * r + y * height) / (r * r + height * height), 0.0f, 1.0f);
    c.slant_rho = w_rho + r * c.slant_t;
    c.slant_y = y - height * c.slant_t;
    /* below the slant line: height rho + r y <= r height */
    c.inside = y >= 0.0f && height * rho + r * y <= r * height;
    return c;
}
SS_FN SDF_FLOAT cone_base_distance2(ConeFeatures c) { return c.base_rho * c.base_rho + c.base_y * c.base_y; }
SS_FN SDF_FLOAT cone_slant_distance2(ConeFeatures c) { return c.slant_rho * c.slant_rho + c.slant_y * c.slant_y; }

/* Exact signed distance: the distance to the nearer of the two segments, negative inside.
 * Lipschitz bound 1. */
SS_FN SDF_FLOAT fCone_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float r, float height) {
    ConeFeatures c = cone_features(radius_y_xz(x, z), y, r, height);
    SDF_FLOAT d = sqrt(fmin(cone_base_distance2(c), cone_slant_distance2(c)));
    return select(d, -d, c.inside);
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fCone(float3 p, float r, float height) { return fCone_xyz(p.x, p.y, p.z, r, height); }

/* Unit outward normal, the gradient of fCone. Inside (and on the surface) it is the outward normal
 * of the nearer face: (0, -1, 0) for the base, (height, r) / |(height, r)| in (rho, y) for the
 * slant (the slant wins ties, e.g. on the rim). Outside it is the direction from the nearest point:
 * the face normal again when that point is inside a face, otherwise the direction from the rim or
 * apex. On the axis the radial direction is +x (radial.h). */
SS_FN float3 nCone(float3 p, float r, float height) {
    float rho = radius_y(p);
    ConeFeatures c = cone_features(rho, p.y, r, height);
    float slant_len = length(make_float2(height, r));
    float3 slant_normal = meridian_to_world(p, height / slant_len, r / slant_len);
    float3 base_normal = make_float3(0.0f, -1.0f, 0.0f);
    float base2 = cone_base_distance2(c);
    float slant2 = cone_slant_distance2(c);
    if (!c.inside) {
        if (base2 < slant2) {
            float l = sqrt(base2);
            if (rho > r && l > 0.0f) return meridian_to_world(p, c.base_rho / l, c.base_y / l);
            return base_normal;
        }
        float l = sqrt(slant2);
        bool at_vertex = c.slant_t <= 0.0f || c.slant_t >= 1.0f;
        if (at_vertex && l > 0.0f) return meridian_to_world(p, c.slant_rho / l, c.slant_y / l);
        return slant_normal;
    }
    if (base2 < slant2) return base_normal;
    return slant_normal;
}
#endif

#endif
