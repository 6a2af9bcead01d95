/* Random numbers for the path tracers: a pure function of (pixel, sample index, seed) and the draw
 * order, so a render needs no per-pixel generator state kept between launches, any sample can be
 * recomputed alone, and the same seed gives the same image on every device and in any launch order.
 *
 * One counter-based Philox4x32-10 call (Salmon et al. 2011, "Parallel random numbers: as easy as 1,
 * 2, 3") per path maps (pixel, sample) under the seed's key to 128 random bits; they seed a
 * xoshiro128** generator (Blackman and Vigna 2018, "Scrambled linear pseudorandom number
 * generators") that gives the path's numbers, four per rng_next4. Philox for every draw (ten rounds,
 * four 32x32->64 multiplies each, per four numbers) took 17 to 22 % of the path tracer's time on one
 * sphere under courtyard.exr, this takes 8 to 10 % (docs/render.md, "Random numbers"). A xoshiro128**
 * step is a few shifts, xors and two small multiplies, all 32-bit. Philox keeps ten rounds: seven
 * saved 1.5 to 3.5 %, within the noise. Streams of different paths start at independent uniform
 * points of xoshiro's 2^128 - 1 period and a path draws at most a few hundred numbers, so two paths'
 * sequences overlap with negligible probability. */
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

/* The high word of a 32x32-bit product, from the 64-bit product on both sides: PoCL's mul_hi made
 * the seeding Philox call about 5 % of the path tracer's time on one sphere (docs/render.md). */
SS_FN uint philox_mul_hi(uint a, uint b) {
#ifdef __OPENCL_C_VERSION__
    return (uint)(((ulong)a * (ulong)b) >> 32);
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

/* Ten rounds, the key bumped by the Weyl constants between rounds. Unrolled in kernels: the
 * camera step of a far sphere (every camera ray a miss) ran 1.08x faster (median of eight renders). */
SS_FN Philox4 philox4x32_10(Philox4 counter, uint k0, uint k1) {
#ifdef __OPENCL_C_VERSION__
#pragma unroll
#endif
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

/* The state of one path's generator: xoshiro128**'s four words. */
typedef struct Rng {
    uint s0, s1, s2, s3;
} Rng;

SS_FN uint rng_rotl(uint x, int k) { return (x << k) | (x >> (32 - k)); }

/* One xoshiro128** step: the next 32 bits. */
SS_FN uint rng_next_uint(Rng* r) {
    uint result = rng_rotl(r->s1 * 5u, 7) * 9u;
    uint t = r->s1 << 9;
    r->s2 ^= r->s0;
    r->s3 ^= r->s1;
    r->s1 ^= r->s2;
    r->s0 ^= r->s3;
    r->s2 ^= t;
    r->s3 = rng_rotl(r->s3, 11);
    return result;
}

/* The generator of sample `sample` of pixel `pixel`: Philox of the counter (pixel, sample, 0, 0)
 * under the key (seed_lo, seed_hi). */
SS_FN Rng rng_make(uint pixel, uint sample, uint seed_lo, uint seed_hi) {
    Philox4 c;
    c.v[0] = pixel;
    c.v[1] = sample;
    c.v[2] = 0u;
    c.v[3] = 0u;
    Philox4 x = philox4x32_10(c, seed_lo, seed_hi);
    Rng r;
    r.s0 = x.v[0];
    r.s1 = x.v[1];
    r.s2 = x.v[2];
    r.s3 = x.v[3];
    if ((r.s0 | r.s1 | r.s2 | r.s3) == 0u) r.s0 = 1u; /* xoshiro's one fixed point (probability 2^-128) */
    return r;
}

/* The path's next four numbers, in order. */
SS_FN float4 rng_next4(Rng* r) {
    float a = uint_to_unit_float(rng_next_uint(r));
    float b = uint_to_unit_float(rng_next_uint(r));
    float c = uint_to_unit_float(rng_next_uint(r));
    float d = uint_to_unit_float(rng_next_uint(r));
    return make_float4(a, b, c, d);
}

#endif
