#include "render/light_cache.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/input_error.hpp"
#include "common/message_number.hpp"

namespace lab::render {

int light_cache_paths(const RenderSettings& settings) {
    const double pixels = double(settings.width) * double(settings.height);
    return int(std::max(1.0, std::round(double(settings.bdpt.light_paths) * pixels)));
}

int light_cache_slots(const RenderSettings& settings) { return bdpt_max_vertices(settings) - 1; }

size_t light_cache_bytes(const RenderSettings& settings) {
    return size_t(light_cache_paths(settings)) * size_t(light_cache_slots(settings)) * size_t(BDPT_CACHE_VERTEX_BYTES);
}

void set_light_cache_weights(const RenderSettings& settings, uint64_t pilot_vertices, kernel::RenderKernelSettings* launch_settings) {
    const double paths = light_cache_paths(settings);
    const double mean = pilot_vertices > 0 ? double(pilot_vertices) / paths : 1.0;
    launch_settings->bdpt.light_tracing_samples = float(paths / (double(settings.width) * double(settings.height)));
    launch_settings->bdpt.connection_samples = float(double(settings.bdpt.connections) / mean);
}

void launch_light_cache_samples(const RenderSettings& settings, const kernel::RenderKernelSettings& launch_settings,
                                const kernel::RenderKernelSettings& pilot_settings, bool first_range, int64_t* pilot_vertices,
                                const LightCachePasses& passes) {
    if (*pilot_vertices < 0) *pilot_vertices = passes.pilot(pilot_settings);
    for (int i = 0; i < launch_settings.sample_count; ++i) {
        kernel::RenderKernelSettings sample_settings = launch_settings;
        sample_settings.first_sample = launch_settings.first_sample + i;
        sample_settings.sample_count = 1;
        set_light_cache_weights(settings, uint64_t(*pilot_vertices), &sample_settings);
        passes.light(sample_settings, first_range);
        passes.pixels(sample_settings);
    }
}

void check_light_cache_settings(const RenderSettings& settings) {
    const float ratio = settings.bdpt.light_paths;
    if (!(ratio > 0.0f && ratio <= kMaxLightPathsPerPixel))
        throw InputError("--light-paths", "", "light subpaths per pixel must be in (0, 16], got " + message_number(ratio));
    if (settings.bdpt.connections < 1 || settings.bdpt.connections > kMaxConnections)
        throw InputError("--connections", "", "must be in [1, 64], got " + std::to_string(settings.bdpt.connections));
    if (integrator_descriptor(settings.integrator).light_cache && light_cache_bytes(settings) > kMaxLightCacheBytes)
        throw InputError("--light-paths", "",
                         "the light-vertex cache would take " + std::to_string(light_cache_bytes(settings) >> 20) +
                             " MiB (light subpaths x (max depth + 1) x 128 bytes), more than 1024: fewer light paths per pixel, a smaller "
                             "image or a smaller --max-depth");
}

}  // namespace lab::render
