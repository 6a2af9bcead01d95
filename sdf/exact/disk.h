/* Exact ray intersection of sdf/primitives/disk.h: the disk of radius r about the origin in the
 * plane of the unit normal n, from either side. */
#ifndef SDF_EXACT_DISK_H
#define SDF_EXACT_DISK_H

#include "single_source/vocabulary.h"
#include "sdf/exact/interval.h"

/* The plane's crossing t = -n.o / n.v, kept where the point lies within r of the centre. */
SS_FN float xDisk(float3 o, float3 v, float3 n, float r, float t_max) {
    float t = -dot(n, o) / dot(n, v);
    float3 q = o + v * t;
    return t > 0.0f && t <= t_max && dot(q, q) <= r * r ? t : EXACT_MISS;
}

#ifdef SDF_LANES /* the lane form (sdf/exact/interval.h) */
SS_FN SDF_FLOAT xDisk_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, float3 n, float r, SDF_FLOAT t_max) {
    SDF_FLOAT t = -(n.x * ox + n.y * oy + n.z * oz) / (n.x * vx + n.y * vy + n.z * vz);
    SDF_FLOAT qx = ox + vx * t, qy = oy + vy * t, qz = oz + vz * t;
    return select((SDF_FLOAT)EXACT_MISS, t, t > 0.0f && t <= t_max && qx * qx + qy * qy + qz * qz <= r * r);
}
#endif

#endif
