/* Random numbers for the path tracers: a pure function of (pixel, sample index, seed) and the draw
 * order, so a render needs no per-pixel generator state kept between launches, any sample can be
 * recomputed alone, and the same seed gives the same image on every device and in any launch order.
 *
 * One counter-based Philox4x32-10 call (Salmon et al. 2011, "Parallel random numbers: as easy as 1,
 * 2, 3") per path maps (pixel, sample) under the seed's key to 128 random bits; they seed a
 * xoshiro128** generator (Blackman and Vigna 2018, "Scrambled linear pseudorandom number
 * generators") that gives the path's numbers, four per rng_next4. Philox for every draw (ten rounds,
 * four 32x32->64 multiplies each, per four numbers) would take 17 to 22 % of the path tracer's time on
 * one sphere under courtyard.exr, this takes 8 to 10 % (docs/render.md, "Random numbers"). A xoshiro128**
 * step is a few shifts, xors and two small multiplies, all 32-bit. Philox keeps ten rounds: seven
 * would save 1.5 to 3.5 %, within the noise. Streams of different paths start at independent uniform
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

/* One round on the words v0 .. v3 under the key (k0, k1), in place: TYPE uint, or SDF_UINT for
 * the lanes of a packet kernel (below), MUL_HI the high word of a 32x32-bit product of that type.
 * One definition for both forms, so a lane computes what the one-lane generator computes. */
#define PHILOX4X32_ROUND(TYPE, MUL_HI, v0, v1, v2, v3, k0, k1) \
    {                                                          \
        TYPE hi0 = MUL_HI(PHILOX_M0, v0), lo0 = PHILOX_M0 * v0; \
        TYPE hi1 = MUL_HI(PHILOX_M1, v2), lo1 = PHILOX_M1 * v2; \
        v0 = hi1 ^ v1 ^ (k0);                                  \
        v1 = lo1;                                              \
        v2 = hi0 ^ v3 ^ (k1);                                  \
        v3 = lo0;                                              \
    }

/* Ten rounds, the key bumped by the Weyl constants between rounds. Unrolled in kernels: a far
 * sphere (every camera ray a miss, the camera step half its time) renders 1.08x faster so. */
#define PHILOX4X32_10(TYPE, MUL_HI, v0, v1, v2, v3, key0, key1)     \
    {                                                               \
        uint k0_ = (key0), k1_ = (key1);                            \
        SS_PRAGMA_UNROLL                                            \
        for (int round_ = 0; round_ < 10; ++round_) {               \
            if (round_ > 0) {                                       \
                k0_ += PHILOX_W0;                                   \
                k1_ += PHILOX_W1;                                   \
            }                                                       \
            PHILOX4X32_ROUND(TYPE, MUL_HI, v0, v1, v2, v3, k0_, k1_) \
        }                                                           \
    }

SS_FN Philox4 philox4x32_10(Philox4 counter, uint k0, uint k1) {
    uint v0 = counter.v[0], v1 = counter.v[1], v2 = counter.v[2], v3 = counter.v[3];
    PHILOX4X32_10(uint, philox_mul_hi, v0, v1, v2, v3, k0, k1)
    Philox4 out;
    out.v[0] = v0;
    out.v[1] = v1;
    out.v[2] = v2;
    out.v[3] = v3;
    return out;
}

/* The top 24 bits fill a float's mantissa exactly: uniform in [0, 1), never 1. */
SS_FN float uint_to_unit_float(uint x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

/* The state of one path's generator: xoshiro128**'s four words. */
typedef struct Rng {
    uint s0, s1, s2, s3;
} Rng;

/* One xoshiro128** step of the words s0 .. s3 (TYPE uint, or SDF_UINT lanes), in place; `result`
 * gets the step's 32 bits. One definition for the generator and its lanes, as PHILOX4X32_ROUND. */
#define XOSHIRO128SS_STEP(TYPE, s0, s1, s2, s3, result)                 \
    {                                                                   \
        TYPE x5_ = (s1) * 5u;                                           \
        result = ((x5_ << 7) | (x5_ >> 25)) * 9u;                       \
        TYPE t_ = (s1) << 9;                                            \
        s2 ^= s0;                                                       \
        s3 ^= s1;                                                       \
        s1 ^= s2;                                                       \
        s0 ^= s3;                                                       \
        s2 ^= t_;                                                       \
        s3 = (s3 << 11) | (s3 >> 21);                                   \
    }

/* One xoshiro128** step: the next 32 bits. */
SS_FN uint rng_next_uint(Rng* r) {
    uint result;
    XOSHIRO128SS_STEP(uint, r->s0, r->s1, r->s2, r->s3, result)
    return result;
}

/* Generator `stream` of sample `sample` of pixel `pixel`: Philox of the counter
 * (pixel, sample, stream, 0) under the key (seed_lo, seed_hi). Stream 0 is the sample's path;
 * BDPT gives each connection strategy a stream of its own (kernels/bdpt.h). */
SS_FN Rng rng_make_stream(uint pixel, uint sample, uint stream, uint seed_lo, uint seed_hi) {
    Philox4 c;
    c.v[0] = pixel;
    c.v[1] = sample;
    c.v[2] = stream;
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

/* The generator of sample `sample` of pixel `pixel`: stream 0. */
SS_FN Rng rng_make(uint pixel, uint sample, uint seed_lo, uint seed_hi) { return rng_make_stream(pixel, sample, 0u, seed_lo, seed_hi); }

/* The path's next four numbers, in order. */
SS_FN float4 rng_next4(Rng* r) {
    float a = uint_to_unit_float(rng_next_uint(r));
    float b = uint_to_unit_float(rng_next_uint(r));
    float c = uint_to_unit_float(rng_next_uint(r));
    float d = uint_to_unit_float(rng_next_uint(r));
    return make_float4(a, b, c, d);
}

#ifdef SDF_LANES
/* The generators of eight paths at once, on the vector lanes of a packet kernel (the wavefront's
 * camera rays, kernels/march_packets.cl): each lane the words of rng_make and rng_next_uint for its
 * path, to the bit. */
typedef struct RngLanes {
    SDF_UINT s0, s1, s2, s3;
} RngLanes;

SS_FN SDF_UINT philox_mul_hi_lanes(uint a, SDF_UINT b) { return convert_uint8((convert_ulong8(b) * (ulong)a) >> 32); }

SS_FN RngLanes rng_make_lanes(SDF_UINT pixel, SDF_UINT sample, uint seed_lo, uint seed_hi) {
    SDF_UINT v0 = pixel, v1 = sample, v2 = (SDF_UINT)0u, v3 = (SDF_UINT)0u;
    PHILOX4X32_10(SDF_UINT, philox_mul_hi_lanes, v0, v1, v2, v3, seed_lo, seed_hi)
    RngLanes r;
    r.s0 = select(v0, (SDF_UINT)1u, (v0 | v1 | v2 | v3) == 0u); /* rng_make's fixed point */
    r.s1 = v1;
    r.s2 = v2;
    r.s3 = v3;
    return r;
}

/* Each lane's next number in [0, 1), as uint_to_unit_float(rng_next_uint()). */
SS_FN SDF_FLOAT rng_next_float_lanes(RngLanes* r) {
    SDF_UINT x;
    XOSHIRO128SS_STEP(SDF_UINT, r->s0, r->s1, r->s2, r->s3, x)
    return convert_float8(x >> 8) * (1.0f / 16777216.0f);
}
#endif

#endif
