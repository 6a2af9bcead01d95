/* Sampling a piecewise-constant 2D distribution over a grid of `rows` x `columns` cells, stored as
 * cumulative distribution functions (pbrt-v4, section A.5.2 "Piecewise-constant 2D distributions",
 * with the marginal over rows and one conditional per row over its columns):
 *
 *   marginal[r]                      r = 0 .. rows,    marginal[0] = 0, marginal[rows] = 1
 *   conditional[row * (columns + 1) + c]  c = 0 .. columns, each row's cdf from 0 to 1
 *
 * Cell (row, c) has probability (marginal[row + 1] - marginal[row]) *
 * (conditional[row, c + 1] - conditional[row, c]). The sampler picks cell k of a cdf exactly when
 * cdf[k] <= u < cdf[k + 1], so these differences, taken from the very floats the sampler compares
 * with, are the probabilities it realises, rounding included.
 * The cdfs are built on the host (ibl/distribution.hpp). */
#ifndef IBL_DISTRIBUTION2D_H
#define IBL_DISTRIBUTION2D_H

#include "single_source/vocabulary.h"

/* The largest float below 1: keeps a uniform number and a remapped offset inside [0, 1). */
#define DISTRIBUTION_ONE_MINUS_EPSILON 0x1.fffffep-1f

/* Index k in [0, n) with cdf[k] <= u < cdf[k + 1] (binary search over the n + 1 entries), and the
 * position of u inside that interval, (u - cdf[k]) / (cdf[k + 1] - cdf[k]) in [0, 1), which is
 * uniform and independent of k: it is reused as a fresh uniform number (pbrt's continuous sample). */
SS_FN int distribution1d_sample(GLOBAL_MEM const float* cdf, int n, float u, float* offset) {
    u = fmin(fmax(u, 0.0f), DISTRIBUTION_ONE_MINUS_EPSILON);
    int lo = 0, hi = n; /* invariant: cdf[lo] <= u < cdf[hi] (cdf[n] = 1 > u) */
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

SS_FN float distribution1d_probability(GLOBAL_MEM const float* cdf, int k) { return cdf[k + 1] - cdf[k]; }

/* A cell of the 2D distribution from two uniform numbers, and the uniform offsets inside it. */
SS_FN void distribution2d_sample(GLOBAL_MEM const float* marginal, GLOBAL_MEM const float* conditional, int rows,
                                   int columns, float u_row, float u_column, int* row, int* column, float* row_offset,
                                   float* column_offset) {
    *row = distribution1d_sample(marginal, rows, u_row, row_offset);
    *column = distribution1d_sample(conditional + *row * (columns + 1), columns, u_column, column_offset);
}

SS_FN float distribution2d_probability(GLOBAL_MEM const float* marginal, GLOBAL_MEM const float* conditional,
                                         int columns, int row, int column) {
    return distribution1d_probability(marginal, row) *
           distribution1d_probability(conditional + row * (columns + 1), column);
}

#endif
