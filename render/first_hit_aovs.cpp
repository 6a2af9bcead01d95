// Renderer::first_hit_aovs: the first-hit AOVs (kernels/first_hit.h) of the film's samples, on the
// host's threads (OpenClRenderer overrides it with the same code as a kernel). One march per
// sample, against a path's several marches and shadow rays, and only when a caller asks (`--aov`):
// a render without AOVs runs none of this.
#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

#include "common/parallel_for.hpp"
#include "render/host_kernels.hpp"
#include "render/renderer.hpp"

namespace lab::render {

FirstHitAovs Renderer::first_hit_means(const std::vector<brdf::float4>& albedo_sums, const std::vector<brdf::float4>& normal_depth_sums,
                                       std::vector<int> slots, int64_t samples) const {
    const int width = input_.settings.width, height = input_.settings.height;
    const size_t pixels = size_t(width) * size_t(height);
    FirstHitAovs aovs{film::ImageRgb(width, height), film::ImageRgb(width, height), std::vector<float>(pixels, 0.0f), std::vector<float>(pixels, 0.0f),
                      std::move(slots)};
    if (samples == 0) return aovs;
    const float scale = float(1.0 / double(samples));
    for (size_t p = 0; p < aovs.depth.size(); ++p) {
        for (int c = 0; c < 3; ++c) {
            aovs.albedo.rgb[3 * p + size_t(c)] = albedo_sums[p][c] * scale;
            aovs.normal.rgb[3 * p + size_t(c)] = normal_depth_sums[p][c] * scale;
        }
        aovs.depth[p] = normal_depth_sums[p][3] * scale;
        aovs.coverage[p] = albedo_sums[p][3] * scale;
    }
    return aovs;
}

FirstHitAovs Renderer::first_hit_aovs() const {
    if (pass_pixels_ > 0) throw std::logic_error("Renderer::first_hit_aovs: a pass is in progress (add_samples ended inside a pass)");
    return first_hit_aovs(sample_ranges());
}

FirstHitAovs Renderer::first_hit_aovs(const SampleRanges& ranges) const { return *first_hit_aovs(ranges, {}); }

std::optional<FirstHitAovs> Renderer::first_hit_aovs(const SampleRanges& ranges, const std::function<bool()>& cancelled) const {
    const int pixels = input_.settings.width * input_.settings.height;
    std::vector<brdf::float4> albedo(size_t(pixels), brdf::float4(0.0f)), normal_depth(size_t(pixels), brdf::float4(0.0f));
    std::vector<int> slots(size_t(pixels), -1);
    const int64_t slot_sample = ranges.empty() ? -1 : ranges.ranges().front().first;
    const kernel::RenderScene scene = host_render_scene();
    const kernel::RenderKernelSettings settings = kernel_settings(0, 0);
    const int piece = cancelled ? kFirstHitPiece : pixels;
    for (int begin = 0; begin < pixels; begin += piece) {
        if (cancelled && cancelled()) return std::nullopt;
        const int end = std::min(pixels, begin + piece);
        std::atomic<int> next{begin};
        auto work = [&] {
            const HostSceneScope scene_scope(input_.scene);
            for (int pixel = next++; pixel < end; pixel = next++)
                for (const auto& [first, last] : ranges.ranges())
                    for (int64_t sample = first; sample < last; ++sample) {
                        const host_kernels::FirstHit h = host_kernels::first_hit_sample(&settings, &camera_, &scene, pixel, int(sample));
                        albedo[size_t(pixel)] += brdf::float4(h.albedo, h.coverage);
                        normal_depth[size_t(pixel)] += brdf::float4(h.normal, h.depth);
                        if (sample == slot_sample) slots[size_t(pixel)] = h.slot;
                    }
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < hardware_threads(); ++t) pool.emplace_back(work);
        work();
        for (std::thread& t : pool) t.join();
    }
    return first_hit_means(albedo, normal_depth, std::move(slots), ranges.count());
}

}  // namespace lab::render
