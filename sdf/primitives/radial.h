/* The solids of revolution about the y axis (torus, cylinder, cone) work in the meridian half-plane
 * (rho = |p.xz|, y); their normals map a direction of that plane back to 3D with this. */
#ifndef SDF_PRIMITIVES_RADIAL_H
#define SDF_PRIMITIVES_RADIAL_H

#include "single_source/vocabulary.h"

/* Distance from the y axis. */
SS_FN SDF_FLOAT radius_y_xz(SDF_FLOAT x, SDF_FLOAT z) { return sqrt(x * x + z * z); }


#ifndef SDF_LANES /* the float3 forms and the normals: scalar code only */
SS_FN float radius_y(float3 p) { return radius_y_xz(p.x, p.z); }

/* Unit direction from the y axis towards p, in the xz plane; +x on the axis itself, where every
 * direction is as good. */
SS_FN float3 radial_direction_y(float3 p) {
    float rho = radius_y(p);
    if (rho > 0.0f) return make_float3(p.x / rho, 0.0f, p.z / rho);
    return make_float3(1.0f, 0.0f, 0.0f);
}

/* The 3D direction of the meridian-plane direction (d_rho, d_y) at p. */
SS_FN float3 meridian_to_world(float3 p, float d_rho, float d_y) {
    return radial_direction_y(p) * d_rho + make_float3(0.0f, d_y, 0.0f);
}
#endif

#endif
