/* Capped cylinder around the y axis, centred at the origin: radius r, from y = -half_height to
 * y = +half_height. */
#ifndef SDF_PRIMITIVES_CYLINDER_H
#define SDF_PRIMITIVES_CYLINDER_H

#include "single_source/vocabulary.h"
#include "sdf/primitives/radial.h"

/* Exact signed distance. In the meridian half-plane (rho = |p.xz|, y) the cylinder is the
 * rectangle [0, r] x [-half_height, half_height], whose axis edge is interior to the solid of
 * revolution; so this is the 2D box distance of (rho, |y|) against (r, half_height), the same
 * construction as fBox. Lipschitz bound 1. */
SS_FN SDF_FLOAT fCylinder_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float r, float half_height) {
    SDF_FLOAT qx = radius_y_xz(x, z) - r, qy = fabs(y) - half_height;
    SDF_FLOAT ox = fmax(qx, 0.0f), oy = fmax(qy, 0.0f);
    return sqrt(ox * ox + oy * oy) + fmin(fmax(qx, qy), 0.0f);
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fCylinder(float3 p, float r, float half_height) { return fCylinder_xyz(p.x, p.y, p.z, r, half_height); }

/* Unit outward normal, the gradient of fCylinder: outside, from the nearest point (side, cap or
 * rim); inside or on the surface, the nearest of side and cap (ties go to the side). On the axis
 * the side direction is taken as +x. */
SS_FN float3 nCylinder(float3 p, float r, float half_height) {
    float y_sign = p.y < 0.0f ? -1.0f : 1.0f;
    float2 q = make_float2(radius_y(p) - r, fabs(p.y) - half_height);
    float2 outside = fmax(q, make_float2(0.0f, 0.0f));
    float l = length(outside);
    if (l > 0.0f) return meridian_to_world(p, outside.x / l, y_sign * (outside.y / l));
    if (q.x >= q.y) return radial_direction_y(p);
    return make_float3(0.0f, y_sign, 0.0f);
}
#endif

#endif
