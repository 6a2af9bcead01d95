/* Torus around the y axis, centred at the origin: the circle of radius major in the xz plane,
 * thickened by minor (0 < minor <= major for a ring torus). */
#ifndef SDF_PRIMITIVES_TORUS_H
#define SDF_PRIMITIVES_TORUS_H

#include "single_source/vocabulary.h"
#include "sdf/primitives/radial.h"

/* Exact signed distance: the distance to the core circle minus minor. In the meridian half-plane
 * (rho = |p.xz|, y) the core circle is the point (major, 0), so that distance is
 * |(rho - major, y)|. Lipschitz bound 1. */
SS_FN SDF_FLOAT fTorus_xyz(SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT z, float major, float minor) {
    SDF_FLOAT q = radius_y_xz(x, z) - major;
    return sqrt(q * q + y * y) - minor;
}

#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float fTorus(float3 p, float major, float minor) { return fTorus_xyz(p.x, p.y, p.z, major, minor); }

/* Unit outward normal: from the nearest point of the core circle towards p. On the y axis every
 * point of the circle is nearest; +x is taken. Undefined on the core circle itself ((0,1,0)). */
SS_FN float3 nTorus(float3 p, float major, float minor) {
    (void)minor;
    float3 v = p - radial_direction_y(p) * major;
    float l = length(v);
    if (!(l > 0.0f)) return make_float3(0.0f, 1.0f, 0.0f);
    return v / l;
}
#endif

#endif
