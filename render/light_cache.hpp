// The light-vertex cache's sizes and weights (`--integrator bdpt-cache`, kernels/bdpt_cache.h,
// docs/bdpt.md): how many light subpaths a sample index traces, how many bytes their vertices take,
// and the connections' sample count in the MIS weights. Both renderers size and weight their cache
// from here, so the host and OpenCL builds render the same estimator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "kernels/host.hpp"
#include "render/render_settings.hpp"

namespace lab::render {

// The options' ranges (check_light_cache_settings).
constexpr float kMaxLightPathsPerPixel = 16.0f;
constexpr int kMaxConnections = 64;
// The most bytes the cache's vertices may take (N_L light subpaths of max_vertices - 1 slots).
constexpr size_t kMaxLightCacheBytes = size_t(1) << 30;

// N_L: --light-paths times the image's pixels, at least 1.
int light_cache_paths(const RenderSettings& settings);
// Vertex slots per light subpath: a light subpath has at most max_vertices - 1 vertices.
int light_cache_slots(const RenderSettings& settings);
// The vertex buffer's bytes (BDPT_CACHE_VERTEX_BYTES a vertex, whatever the device's layout).
size_t light_cache_bytes(const RenderSettings& settings);

// The sample index of the pilot pool: N_L light subpaths, never a render's sample (indices run from
// 0 up), whose mean number of connectable vertices sets the connections' weight below. A constant
// of the render (the scene, the seed, the settings), not of the sample: the weights are the same
// functions of the path for every sample, so the estimator stays unbiased whatever the pool of a
// sample holds, and any sample range gets the same weights.
constexpr int kLightCachePilotSample = -1;

// The launch settings of the cache: light_tracing_samples N_L / N_pixels (each camera subpath's
// share of the light subpaths that splat), connection_samples M / (pilot_vertices / N_L) (the
// times a camera vertex is joined to a given connectable light vertex, in expectation over the
// choice). A pilot without connectable vertices leaves their mean at 1: the weights only need to
// sum to 1, and no sample's pool is likely to hold any either.
void set_light_cache_weights(const RenderSettings& settings, uint64_t pilot_vertices, kernel::RenderKernelSettings* launch_settings);

// What a renderer does for the cache, on its own device: trace the pilot pool (no splats, its rays
// counted in no render) and return its connectable vertices; trace one sample index's pool,
// splatting its t = 1 strategies when `splats`; join the launch's pixels to that pool.
struct LightCachePasses {
    std::function<int64_t(const kernel::RenderKernelSettings&)> pilot;
    std::function<void(const kernel::RenderKernelSettings&, bool splats)> light;
    std::function<void(const kernel::RenderKernelSettings&)> pixels;
};

// One launch of the cache over a pixel range, the same for every renderer: the pilot once per
// state (*pilot_vertices < 0 until then, from `pilot_settings`), then for each sample index of
// `launch_settings` its pool and its pixels. A pass split into pixel ranges traces each pool for
// every range and splats it from the range that starts the image only (`first_range`).
void launch_light_cache_samples(const RenderSettings& settings, const kernel::RenderKernelSettings& launch_settings,
                                const kernel::RenderKernelSettings& pilot_settings, bool first_range, int64_t* pilot_vertices,
                                const LightCachePasses& passes);

// Throws lab::InputError naming --light-paths or --connections when out of range, or --light-paths
// when the cache would take more than kMaxLightCacheBytes. Called by check_render_settings.
void check_light_cache_settings(const RenderSettings& settings);

}  // namespace lab::render
