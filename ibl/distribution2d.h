/* Sampling a piecewise-constant 2D distribution over a grid of `rows` x `columns` cells, stored as
 * cumulative distribution functions (pbrt-v4, section A.5.2 "Piecewise-constant 2D distributions",
 * with the marginal over rows and one conditional per row over its columns):
 *
 *   marginal[r]                      r = 0 .. rows,    marginal[0] = 0, marginal[rows] = 1
 *   conditional[row * (columns + 1) + c]  c = 0 .. columns, each row's cdf from 0 to 1
 *
 * and, to find the interval of u without a binary search over the whole cdf, a guide table per cdf
 * (the cutpoint method, Chen and Asau 1974; Devroye, "Non-Uniform Random Variate Generation", II.2.4):
 * for a cdf of n cells and a power of two G (distribution_guide_size(n)),
 *
 *   guide[m] = the largest k < n with cdf[k] <= m / G,   m = 0 .. G - 1,
 *
 * so for u in [m / G, (m + 1) / G) the cell lies in [guide[m], guide[m + 1]] (to n - 1 for the last
 * m), and a search of that range, usually one or two cells, finds the very cell the full binary
 * search finds: u * G is exact for a power of two, so the bucket of u is exactly m.
 *   guide[m]                          the marginal's, m = 0 .. G_rows - 1
 *   guide[G_rows + row * G_columns + m]  row's conditional's, m = 0 .. G_columns - 1
 * (ushort: cell indices stay below 65536 for the largest environment, 6 x 4096 rows.)
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

/* The guide table's size for n cells: the smallest power of two >= n (at least one entry per cell). */
SS_FN int distribution_guide_size(int n) {
    int g = 1;
    while (g < n) g *= 2;
    return g;
}

/* The same cell as distribution1d_sample(), searching only the range that guide (guide_size
 * entries, see the top of this file) gives for u's bucket. */
SS_FN int distribution1d_sample_guided(GLOBAL_MEM const float* cdf, GLOBAL_MEM const ushort* guide, int guide_size, int n, float u,
                                       float* offset) {
    u = distribution_clamp_unit(u);
    int m = (int)(u * (float)guide_size); /* exact: guide_size is a power of two */
    int lo = (int)guide[m];
    int hi = m + 1 < guide_size ? (int)guide[m + 1] + 1 : n;
    return distribution1d_search(cdf, lo, hi, u, offset);
}

SS_FN float distribution1d_probability(GLOBAL_MEM const float* cdf, int k) { return cdf[k + 1] - cdf[k]; }

/* A cell of the 2D distribution from two uniform numbers, and the uniform offsets inside it; guide
 * as at the top of this file, with row_guide_size = distribution_guide_size(rows) and
 * column_guide_size = distribution_guide_size(columns). */
SS_FN void distribution2d_sample(GLOBAL_MEM const float* marginal, GLOBAL_MEM const float* conditional, GLOBAL_MEM const ushort* guide,
                                   int rows, int columns, int row_guide_size, int column_guide_size, float u_row, float u_column,
                                   int* row, int* column, float* row_offset, float* column_offset) {
    *row = distribution1d_sample_guided(marginal, guide, row_guide_size, rows, u_row, row_offset);
    *column = distribution1d_sample_guided(conditional + *row * (columns + 1), guide + row_guide_size + *row * column_guide_size,
                                           column_guide_size, columns, u_column, column_offset);
}

SS_FN float distribution2d_probability(GLOBAL_MEM const float* marginal, GLOBAL_MEM const float* conditional,
                                         int columns, int row, int column) {
    return distribution1d_probability(marginal, row) *
           distribution1d_probability(conditional + row * (columns + 1), column);
}

#endif
