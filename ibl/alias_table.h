/* Alias tables (Walker 1977; Vose 1991): a discrete distribution over n cells sampled from one
 * uniform number in constant time with one table lookup, where a cdf needs a search. Entry i keeps
 * cell i with probability `threshold` and otherwise gives its remaining share to cell `alias`:
 *   x = u n,  i = floor(x),  f = x - i:   cell i if f < threshold_i, else alias_i,
 * so that cell k is drawn with probability (threshold_k + sum over i with alias_i = k of
 * (1 - threshold_i)) / n. The position of f inside the part of [0, 1) that chose the cell is
 * uniform and is returned as a fresh number (as pbrt's continuous sample). The tables are built on
 * the host (ibl/alias_table.hpp), which also computes the probability each cell is drawn with when
 * u is a float of the form k 2^-24 (what kernels/rng.h gives), rounding included. */
#ifndef IBL_ALIAS_TABLE_H
#define IBL_ALIAS_TABLE_H

#include "single_source/vocabulary.h"
#include "ibl/distribution1d.h"

/* Plain 4-byte fields: one layout in OpenCL C and C++. */
typedef struct AliasEntry {
    float threshold; /* in [0, 1]: the share of the entry's interval that keeps its own cell */
    int alias;       /* the cell that takes the rest */
} AliasEntry;

/* The entry that u (clamped into [0, 1)) reads, and f, its position in that entry's interval. */
SS_FN int alias_table_entry(int n, float u, float* f) {
    float x = distribution_clamp_unit(u) * (float)n;
    int i = min((int)x, n - 1);
    *f = x - (float)i;
    return i;
}

/* The cell of u among the n cells of `table`, and the offset of u inside the part of [0, 1) that
 * drew it, in [0, 1). */
SS_FN int alias_table_sample(GLOBAL_MEM const AliasEntry* table, int n, float u, float* offset) {
    float f;
    int i = alias_table_entry(n, u, &f);
    AliasEntry e = table[i];
    if (f < e.threshold) {
        *offset = fmin(f / e.threshold, DISTRIBUTION_ONE_MINUS_EPSILON);
        return i;
    }
    *offset = fmin((f - e.threshold) / (1.0f - e.threshold), DISTRIBUTION_ONE_MINUS_EPSILON);
    return e.alias;
}

/* Two levels over a grid of rows x columns cells (the host's build_row_alias_tables,
 * ibl/distribution.hpp): the rows' table of `rows` entries, then row r's of `columns` entries at
 * rows + r columns (alias_grid_column_table). The cell (row, column) that (u1, u2) draws, and the offsets of u1 and u2 inside
 * the parts of [0, 1) that drew it. */
SS_FN GLOBAL_MEM const AliasEntry* alias_grid_column_table(GLOBAL_MEM const AliasEntry* table, int rows, int columns, int row) {
    return table + rows + row * columns;
}
SS_FN void alias_grid_sample(GLOBAL_MEM const AliasEntry* table, int rows, int columns, float u1, float u2, int* row, int* column,
                             float* row_offset, float* column_offset) {
    *row = alias_table_sample(table, rows, u1, row_offset);
    *column = alias_table_sample(alias_grid_column_table(table, rows, columns, *row), columns, u2, column_offset);
}

#endif
