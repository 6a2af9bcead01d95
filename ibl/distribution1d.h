/* Sampling a piecewise-constant 1D distribution over n cells stored as its cumulative distribution
 * function (pbrt-v4, section A.5.1): cdf[0] = 0, ..., cdf[n] = 1, cell k drawn exactly when
 * cdf[k] <= u < cdf[k + 1], so the differences of the very floats the sampler compares with are the
 * probabilities it realises, rounding included. The lights' selection distribution (kernels/lights/
 * light_selection.h); the cdfs are built on the host (ibl/distribution.hpp). The environment's
 * texels are drawn through alias tables instead (ibl/alias_table.h): a cdf over 10^5 or more texels
 * needs a search, and a search in a table of megabytes a chain of cache misses. */
#ifndef IBL_DISTRIBUTION1D_H
#define IBL_DISTRIBUTION1D_H

#include "single_source/vocabulary.h"

/* The largest float below 1: keeps a uniform number and a remapped offset inside [0, 1). */
#define DISTRIBUTION_ONE_MINUS_EPSILON 0x1.fffffep-1f

/* Index k in [lo, hi) with cdf[k] <= u < cdf[k + 1] (binary search, given cdf[lo] <= u < cdf[hi]
 * for u in [0, 1)), and the position of u inside that interval, (u - cdf[k]) / (cdf[k + 1] - cdf[k])
 * in [0, 1), which is uniform and independent of k: it is reused as a fresh uniform number (pbrt's
 * continuous sample). */
SS_FN int distribution1d_search(GLOBAL_MEM const float* cdf, int lo, int hi, float u, float* offset) {
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    float width = cdf[lo + 1] - cdf[lo];
    *offset = width > 0.0f ? fmin((u - cdf[lo]) / width, DISTRIBUTION_ONE_MINUS_EPSILON) : 0.0f;
    return lo;
}

/* u clamped into [0, 1) (a NaN to 0). */
SS_FN float distribution_clamp_unit(float u) { return fmin(fmax(u, 0.0f), DISTRIBUTION_ONE_MINUS_EPSILON); }

/* The cell of u among the n cells of a cdf of n + 1 entries (cdf[n] = 1 > u), searching all of it. */
SS_FN int distribution1d_sample(GLOBAL_MEM const float* cdf, int n, float u, float* offset) {
    return distribution1d_search(cdf, 0, n, distribution_clamp_unit(u), offset);
}

SS_FN float distribution1d_probability(GLOBAL_MEM const float* cdf, int k) { return cdf[k + 1] - cdf[k]; }

#endif
