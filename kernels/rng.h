/* Counter-based random numbers: Philox4x32-10 (Salmon et al. 2011, "Parallel random numbers: as easy
 * as 1, 2, 3"). The numbers of a path are a pure function of (pixel, sample index, seed, draw), so
 * a render needs no per-pixel generator state, any sample can be recomputed alone, and the same
 * seed gives the same image on every device and in any launch order. */
#ifndef KERNELS_RNG_H
#define KERNELS_RNG_H
#include "single_source/vocabulary.h"

#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u /* golden ratio */
#define PHILOX_W1 0xBB67AE85u /* sqrt(3) - 1 */

typedef struct Philox4 {
    uint v[4];
} Philox4;

SS_FN uint philox_mul_hi(uint a, uint b) {
#ifdef __OPENCL_C_VERSION__
    return mul_hi(a, b);
#else
    return (uint)(((unsigned long long)a * (unsigned long long)b) >> 32);
#endif
}

SS_FN Philox4 philox4x32_round(Philox4 c, uint k0, uint k1) {
    uint hi0 = philox_mul_hi(PHILOX_M0, c.v[0]), lo0 = PHILOX_M0 * c.v[0];
    uint hi1 = philox_mul_hi(PHILOX_M1, c.v[2]), lo1 = PHILOX_M1 * c.v[2];
    Philox4 out;
    out.v[0] = hi1 ^ c.v[1] ^ k0;
    out.v[1] = lo1;
    out.v[2] = hi0 ^ c.v[3] ^ k1;
    out.v[3] = lo0;
    return out;
}

/* Ten rounds, the key bumped by the Weyl constants between rounds. */
SS_FN Philox4 philox4x32_10(Philox4 counter, uint k0, uint k1) {
    for (int round = 0; round < 10; ++round) {
        if (round > 0) {
            k0 += PHILOX_W0;
            k1 += PHILOX_W1;
        }
        counter = philox4x32_round(counter, k0, k1);
    }
    return counter;
}

/* The top 24 bits fill a float's mantissa exactly: uniform in [0, 1), never 1. */
SS_FN float uint_to_unit_float(uint x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

/* One stream per (pixel, sample); each draw advances a block counter and yields four numbers. */
typedef struct Rng {
    uint pixel, sample, block, key0, key1;
} Rng;

SS_FN Rng rng_make(uint pixel, uint sample, uint seed_lo, uint seed_hi) {
    Rng r;
    r.pixel = pixel;
    r.sample = sample;
    r.block = 0u;
    r.key0 = seed_lo;
    r.key1 = seed_hi;
    return r;
}

SS_FN float4 rng_next4(Rng* r) {
    Philox4 c;
    c.v[0] = r->pixel;
    c.v[1] = r->sample;
    c.v[2] = r->block;
    c.v[3] = 0u;
    r->block += 1u;
    Philox4 x = philox4x32_10(c, r->key0, r->key1);
    return make_float4(uint_to_unit_float(x.v[0]), uint_to_unit_float(x.v[1]), uint_to_unit_float(x.v[2]), uint_to_unit_float(x.v[3]));
}

#endif
