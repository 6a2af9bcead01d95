// Renderer::first_hit_aovs: the first-hit AOVs (kernels/first_hit.h) of the film's samples, on the
// host's threads. One march per sample, against a path's several marches and shadow rays, and only
// when a caller asks (`--aov`): a render without AOVs runs none of this.
#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

#include "render/host_kernels.hpp"
#include "render/renderer.hpp"

namespace lab::render {

FirstHitAovs Renderer::first_hit_aovs() const {
    if (pass_pixels_ > 0) throw std::logic_error("Renderer::first_hit_aovs: a pass is in progress (add_samples ended inside a pass)");
    const int width = input_.settings.width, height = input_.settings.height, pixels = width * height;
    FirstHitAovs aovs{film::ImageRgb(width, height), film::ImageRgb(width, height), std::vector<float>(size_t(pixels), 0.0f)};
    const SampleRanges ranges = sample_ranges();
    const double samples = double(ranges.count());
    if (samples == 0.0) return aovs;
    const kernel::RenderScene scene = host_render_scene();
    const kernel::RenderKernelSettings settings = kernel_settings(0, 0);
    std::atomic<int> next{0};
    auto work = [&] {
        const HostSceneScope scene_scope(input_.scene);
        for (int pixel = next++; pixel < pixels; pixel = next++) {
            brdf::float3 albedo(0.0f), normal(0.0f);
            double depth = 0.0;
            for (const auto& [first, end] : ranges.ranges())
                for (int64_t sample = first; sample < end; ++sample) {
                    const host_kernels::FirstHit h = host_kernels::first_hit_sample(&settings, &camera_, &scene, pixel, int(sample));
                    albedo += h.albedo;
                    normal += h.normal;
                    depth += h.depth;
                }
            const float scale = float(1.0 / samples);
            float* a = aovs.albedo.rgb.data() + 3 * size_t(pixel);
            float* n = aovs.normal.rgb.data() + 3 * size_t(pixel);
            for (int c = 0; c < 3; ++c) {
                a[c] = albedo[c] * scale;
                n[c] = normal[c] * scale;
            }
            aovs.depth[size_t(pixel)] = float(depth / samples);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::max(1u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return aovs;
}

}  // namespace lab::render
