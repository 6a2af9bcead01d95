/* A spatial hash grid over the light-vertex cache's vertices (kernels/bdpt_cache.h), for vertex
 * merging (`--integrator vcm`, kernels/vcm.h; docs/bdpt.md, "Vertex connection and merging"). Cells
 * are cubes of side 2 r (r the merge radius), hashed into `size` buckets; the buckets are a counting
 * sort of the cache's vertex indices: bucket h holds entries[cells[h] .. cells[h + 1]). A point's
 * disk of radius r lies within the 2 x 2 x 2 cells nearest it (hash_grid_buckets). Built by one
 * work-item in the cache's vertex order, so the entries' order, and with it every merge's order of
 * summation, is the same on every device and run. */
#ifndef KERNELS_HASH_GRID_H
#define KERNELS_HASH_GRID_H

#include "kernels/bdpt_vertex.h"

/* A coordinate of the cell holding x, for cells of side `cell`, clamped to the int range's middle
 * (a far point of an endless floor would overflow it). */
SS_FN int hash_grid_coordinate(float x, float cell) { return (int)fmin(fmax(floor(x / cell), -1073741824.0f), 1073741824.0f); }

/* The bucket of cell (x, y, z) (Teschner et al. 2003's primes). */
SS_FN uint hash_grid_bucket(int x, int y, int z, uint size) {
    return (((uint)x * 73856093u) ^ ((uint)y * 19349663u) ^ ((uint)z * 83492791u)) % size;
}

SS_FN uint hash_grid_bucket_of(float3 p, float cell, uint size) {
    return hash_grid_bucket(hash_grid_coordinate(p.x, cell), hash_grid_coordinate(p.y, cell), hash_grid_coordinate(p.z, cell), size);
}

/* A vertex merging can use: past the light's own vertex (k >= 1), on a surface. */
SS_FN bool hash_grid_holds(const PathVertex* v, int k) { return k >= 1 && v->type == VERTEX_SURFACE; }

/* Builds the grid of cell side `cell` over the cache's vertices (vertex k of light subpath j at
 * cache[j * slots + k], lengths[j] of them), entries holding j * slots + k. cells has size + 1
 * words, entries paths * slots. */
SS_FN void hash_grid_build(GLOBAL_MEM const PathVertex* cache, GLOBAL_MEM const int* lengths, int paths, int slots, float cell,
                           GLOBAL_MEM uint* cells, GLOBAL_MEM uint* entries, uint size) {
    for (uint h = 0u; h <= size; ++h) cells[h] = 0u;
    for (int j = 0; j < paths; ++j)
        for (int k = 0; k < lengths[j]; ++k) {
            PathVertex v = cache[j * slots + k];
            if (hash_grid_holds(&v, k)) cells[hash_grid_bucket_of(v.p, cell, size) + 1u] += 1u;
        }
    for (uint h = 1u; h <= size; ++h) cells[h] += cells[h - 1u]; /* cells[h]: where bucket h starts */
    for (int j = 0; j < paths; ++j)
        for (int k = 0; k < lengths[j]; ++k) {
            PathVertex v = cache[j * slots + k];
            if (hash_grid_holds(&v, k)) entries[cells[hash_grid_bucket_of(v.p, cell, size)]++] = (uint)(j * slots + k);
        }
    /* each cells[h] now holds where bucket h + 1 starts */
    for (uint h = size; h > 0u; --h) cells[h] = cells[h - 1u];
    cells[0] = 0u;
}

/* The distinct buckets of the 2 x 2 x 2 cells (side `cell` = 2 r) nearest p, which hold every
 * point within r of it: on each axis p's own cell and the neighbour on the side of the cell's
 * half p lies in. Returns their count (1 to 8; two cells can share a bucket, which is then
 * visited once). */
SS_FN int hash_grid_buckets(float3 p, float cell, uint size, uint* buckets) {
    int x = hash_grid_coordinate(p.x, cell), y = hash_grid_coordinate(p.y, cell), z = hash_grid_coordinate(p.z, cell);
    int dx = p.x / cell - (float)x < 0.5f ? -1 : 1;
    int dy = p.y / cell - (float)y < 0.5f ? -1 : 1;
    int dz = p.z / cell - (float)z < 0.5f ? -1 : 1;
    int count = 0;
    for (int i = 0; i < 8; ++i) {
        uint b = hash_grid_bucket(x + ((i & 1) != 0 ? dx : 0), y + ((i & 2) != 0 ? dy : 0), z + ((i & 4) != 0 ? dz : 0), size);
        bool seen = false;
        for (int m = 0; m < count; ++m) seen = seen || buckets[m] == b;
        if (!seen) buckets[count++] = b;
    }
    return count;
}

#endif
