/* Limited repetition of space: a finite block of copies. */
#ifndef SDF_DOMAIN_MOD_INTERVAL3_H
#define SDF_DOMAIN_MOD_INTERVAL3_H

#include "single_source/vocabulary.h"
#include "sdf/domain/mod3.h"

/* x relative to the nearest of the copies centred on period k, k in [count_min, count_max]
 * (whole numbers, count_min <= count_max); period <= 0 means no repetition along this axis. */
SS_FN SDF_FLOAT pModInterval1(SDF_FLOAT x, float period, float count_min, float count_max) {
    if (!(period > 0.0f)) return x;
    return x - period * clamp(mod_cell(x, period), count_min, count_max);
}

/* Limited repetition: copies centred on period * k for k = count_min..count_max per axis (e.g.
 * count_min = (-2, 0, -2), count_max = (2, 0, 2) is a 5 x 1 x 5 grid in the xz plane). Beyond the
 * outermost copies the field is the outermost copy's own, so it extends continuously.
 * Bound: as pMod3 (see mod3.h): L_f-Lipschitz, and exact for the whole block, when the shape fits
 * inside its cell and is symmetric about the cell's mid-planes; otherwise the field jumps at the
 * faces between copies and the bound is broken. */
#ifndef SDF_LANES /* scalar code only */
SS_FN float3 pModInterval3(float3 p, float3 period, float3 count_min, float3 count_max) {
    return make_float3(pModInterval1(p.x, period.x, count_min.x, count_max.x),
                       pModInterval1(p.y, period.y, count_min.y, count_max.y),
                       pModInterval1(p.z, period.z, count_min.z, count_max.z));
}
#endif

#endif
