/* Vertex connection and merging (`dtoadq render --integrator vcm`; Georgiev et al. 2012, "Light
 * transport simulation with vertex connection and merging"; Hachisuka et al. 2012, unified path
 * sampling; docs/bdpt.md, "Vertex connection and merging"): the light-vertex cache's estimator
 * (kernels/bdpt_cache.h) and, at every camera vertex that scatters, the merging of the vertex with
 * every cache vertex within the sample's radius r of it, found in a hash grid built over the cache
 * (kernels/hash_grid.h). A merge estimates the camera vertex's outgoing radiance from the light
 * subpath's flux at a point nearby: (1 / N_L) sum_y beta_C f(x, w_y) beta_L(y) / (pi r^2). The radius
 * shrinks with the sample index (render/vcm.cpp), so the bias of the disk's blur vanishes. Merging
 * makes paths no connection can: a diffuse vertex between two delta ones (a caustic seen in a
 * mirror). The MIS weights take connections and merges together (kernels/bdpt_mis.h). Needs the
 * scene declared before it, as kernels/path.h does. */
#ifndef KERNELS_VCM_H
#define KERNELS_VCM_H

#include "kernels/bdpt.h"
#include "kernels/hash_grid.h"

/* The hash grid's cell side: 2 r, so that the 2 x 2 x 2 cells nearest a point hold its disk of
 * radius r (hash_grid_buckets). */
SS_FN float vcm_cell_size(const RenderKernelSettings* settings) { return 2.0f * settings->bdpt.merge_radius; }

/* The MIS weight of merging light vertex light[s - 1] (s >= 2) with camera vertex cam[t - 1]
 * (t >= 2): bdpt_mis_ratio_sum of the path as connection (s, t - 1), whose own 1 counts only where
 * that connection is a strategy of the render (it joins light[s - 1] to a vertex no delta lobe left). */
SS_FN float vcm_merge_weight(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* light,
                             const PathVertex* cam, int s, int t) {
    float merge = 0.0f;
    float sum = bdpt_mis_ratio_sum(settings, camera, scene, light, cam, &cam[0], s, t - 1, 1, &merge);
    bool connection = bdpt_strategy_enabled(settings->bdpt.strategies, s, t - 1) && (t - 1 == 1 || !cam[t - 2].delta);
    return merge > 0.0f ? merge / ((connection ? 1.0f : 0.0f) + sum) : 0.0f;
}

/* The MIS-weighted merges of camera vertex cam[t - 1] (t >= 2) with the cache's vertices within
 * settings->bdpt.merge_radius of it, as a radiance towards the camera. `light` is room for a light
 * subpath, copied from the cache. */
SS_FN float3 vcm_merge_vertex(const RenderKernelSettings* settings, const Camera* camera, const RenderScene* scene, const PathVertex* cam, int t,
                              int max_vertices, GLOBAL_MEM const PathVertex* cache, int slots, int paths, GLOBAL_MEM const uint* cells,
                              GLOBAL_MEM const uint* entries, uint size, PathVertex* light) {
    float3 sum = float3_splat(0.0f);
    const PathVertex* z = &cam[t - 1];
    float r = settings->bdpt.merge_radius;
    /* merges are in every mask's weights; --strategies renders the connections alone */
    if (!(r > 0.0f) || size == 0u || !vertex_scatters(scene, z) || settings->bdpt.single_strategy >= 0) return sum;
    uint buckets[8];
    int count = hash_grid_buckets(z->p, vcm_cell_size(settings), size, buckets);
    for (int b = 0; b < count; ++b)
        for (uint e = cells[buckets[b]]; e < cells[buckets[b] + 1u]; ++e) {
            uint index = entries[e];
            int path = (int)(index / (uint)slots), k = (int)(index % (uint)slots);
            int s = k + 1;
            if (s + t - 1 > max_vertices) continue;
            PathVertex y = cache[index];
            float3 d = y.p - z->p;
            if (dot(d, d) > r * r) continue;
            /* the light arrived at y from light[k - 1]: f at z between the camera's direction and that one */
            float3 c = z->beta * vertex_f(scene, z, frame_to_world(y.frame, y.wo), TRANSPORT_RADIANCE) * y.beta;
            if (!(max_component(c) > 0.0f)) continue;
            for (int i = 0; i <= k; ++i) light[i] = cache[path * slots + i];
            sum += c * vcm_merge_weight(settings, camera, scene, light, cam, s, t);
        }
    return sum * (1.0f / (SS_PI * r * r * (float)paths));
}

/* The grid over one sample index's cache (kernels/hash_grid.h). */
SS_FN void vcm_build_grid(const RenderKernelSettings* settings, GLOBAL_MEM const PathVertex* cache, GLOBAL_MEM const int* lengths, int paths,
                          GLOBAL_MEM uint* cells, GLOBAL_MEM uint* entries, uint size) {
    hash_grid_build(cache, lengths, paths, bdpt_kernel_max_vertices(settings) - 1, vcm_cell_size(settings), cells, entries, size);
}

#endif
