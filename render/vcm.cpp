#include "render/vcm.hpp"

#include <cmath>

#include "common/input_error.hpp"
#include "common/message_number.hpp"
#include "render/light_cache.hpp"

namespace lab::render {

float vcm_base_radius(const RenderSettings& settings, float scene_radius) {
    return settings.bdpt.merge_radius > 0.0f ? settings.bdpt.merge_radius : kMergeRadiusOfScene * scene_radius;
}

void set_vcm_sample_radius(const RenderSettings& settings, int sample, kernel::RenderKernelSettings* launch_settings) {
    const double r = double(launch_settings->bdpt.merge_radius0) * std::pow(double(sample) + 1.0, (double(kMergeRadiusAlpha) - 1.0) / 2.0);
    launch_settings->bdpt.merge_radius = float(r);
    launch_settings->bdpt.merge_samples = float(double(light_cache_paths(settings)) * M_PI * r * r);
}

size_t vcm_grid_buckets(const RenderSettings& settings) { return size_t(light_cache_paths(settings)) * size_t(light_cache_slots(settings)); }

void check_merge_radius(float r) {
    if (!(r > 0.0f && std::isfinite(r))) throw InputError("--merge-radius", "", "must be a positive length, got " + message_number(r));
}

void check_vcm_settings(const RenderSettings& settings) {
    if (settings.bdpt.merge_radius != 0.0f) check_merge_radius(settings.bdpt.merge_radius);
}

}  // namespace lab::render
