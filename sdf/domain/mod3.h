/* Infinite repetition of space (hg_sdf's pMod family, written from the definition). */
#ifndef SDF_DOMAIN_MOD3_H
#define SDF_DOMAIN_MOD3_H

#include "single_source/vocabulary.h"

/* The cell of a coordinate: cells are [period (k - 1/2), period (k + 1/2)), centred on period k.
 * floor(x / period + 1/2) rather than round(), whose halfway case differs between libraries. */
SS_FN SDF_FLOAT mod_cell(SDF_FLOAT x, float period) { return floor(x / period + 0.5f); }

/* x relative to the centre of its cell; period <= 0 means no repetition along this axis. */
SS_FN SDF_FLOAT pMod1(SDF_FLOAT x, float period) {
    if (!(period > 0.0f)) return x;
    return x - period * mod_cell(x, period);
}

/* Infinite repetition: p relative to the centre of its cell, cells centred on the multiples of
 * period (per axis; a component <= 0 leaves that axis unrepeated). Evaluate the shape at the result.
 *
 * Bound. The map is an isometry inside each cell, so f(pMod3(p)) is L_f-Lipschitz inside each cell;
 * it is L_f-Lipschitz everywhere iff it is also continuous across the cell faces, i.e. f takes the
 * same value at opposite points of opposite faces (f(P/2, y, z) = f(-P/2, y, z), ...). That holds
 * when the shape FITS INSIDE ITS CELL AND IS SYMMETRIC about the cell's mid-planes x = 0, y = 0,
 * z = 0 (a centred sphere, box, cylinder, capsule, torus, ...): then its own copy is also the nearest
 * copy (reflection about the shared face maps it onto the neighbour's, which lies on the far side),
 * and the field is the exact distance to the whole array. Otherwise THE BOUND IS BROKEN: a shape
 * that pokes out of its cell is cut at the faces, and a shape off the cell centre has a nearer copy
 * in the neighbouring cell; either way the field jumps at the faces and a ray can step over a copy.
 * (The scene compiler should reject, or at least report, a repeated object whose bounds leave its
 * cell or that is not centred in it.) */
#ifndef SDF_LANES /* scalar code only */
SS_FN float3 pMod3(float3 p, float3 period) {
    return make_float3(pMod1(p.x, period.x), pMod1(p.y, period.y), pMod1(p.z, period.z));
}
#endif

#endif
