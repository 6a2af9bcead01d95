#include "render/host_renderer.hpp"

#include <atomic>
#include <thread>

#include "common/parallel_for.hpp"
#include "render/host_kernels.hpp"
#include "render/light_cache.hpp"
#include "render/vcm.hpp"

namespace lab::render {

size_t path_state_bytes() { return sizeof(host_kernels::PathState); }

HostRenderer::HostRenderer(RenderInput input, int threads) : Renderer(std::move(input)) {
    threads_ = threads > 0 ? threads : hardware_threads();
    initialize();
}

HostRenderer::~HostRenderer() = default;

std::string HostRenderer::device_description() const {
    return "host C++ (" + std::to_string(threads_) + (threads_ == 1 ? " thread)" : " threads)");
}

void HostRenderer::clear_film() {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    film_.accumulation.assign(pixels * 4, 0.0f);
    film_.squares.assign(pixels * 4, 0.0f);
    film_.splat.assign(pixels * 3, 0.0f);
    rays_.assign(pixels, 0u);
    lost_.assign(pixels, 0u);
    if (integrator_descriptor(input_.settings.integrator).light_cache) {
        const size_t paths = size_t(light_cache_paths(input_.settings));
        cache_.resize(paths * size_t(light_cache_slots(input_.settings)));
        cache_lengths_.assign(paths, 0);
        cache_offsets_.assign(paths + 1, 0u);
        cache_rays_.assign(paths, 0u);
        cache_lost_.assign(paths, 0u);
        if (integrator_descriptor(input_.settings.integrator).merges) {
            grid_cells_.assign(vcm_grid_buckets(input_.settings) + 1, 0u);
            grid_entries_.assign(vcm_grid_buckets(input_.settings), 0u);
        }
    }
    if (!integrator_descriptor(input_.settings.integrator).merges) {
        grid_cells_.clear();
        grid_entries_.clear();
    }
    pilot_vertices_ = -1;  // the scene, camera or settings may have changed
}

void HostRenderer::parallel_for(int first, int end, int chunk, const std::function<void(int)>& item) const {
    std::atomic<int> next{first};
    auto work = [&] {
        const HostSceneScope scene_scope(input_.scene);
        for (int begin = next.fetch_add(chunk); begin < end; begin = next.fetch_add(chunk))
            for (int i = begin; i < std::min(end, begin + chunk); ++i) item(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads_; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

void HostRenderer::launch(const kernel::RenderKernelSettings& launch_settings, PixelRange range) {
    if (integrator_descriptor(input_.settings.integrator).light_cache) {
        launch_light_cache(launch_settings, range);
        return;
    }
    const kernel::RenderScene scene = host_render_scene();
    auto* accumulation = reinterpret_cast<brdf::float4*>(film_.accumulation.data());
    auto* squares = reinterpret_cast<brdf::float4*>(film_.squares.data());
    // The splat buffer holds floats as their bits (kernels/film.h), which the film reads back as floats.
    auto* splat = reinterpret_cast<unsigned*>(film_.splat.data());
    const bool bidirectional = integrator_descriptor(input_.settings.integrator).bidirectional();
    // Rows of pixels at a time: few enough atomics, small enough to balance the threads.
    parallel_for(range.first, range.first + range.count, std::max(1, input_.settings.width), [&](int pixel) {
        if (bidirectional)
            host_kernels::bdpt_pixel(&launch_settings, &camera_, &scene, pixel, accumulation, squares, splat, rays_.data(), lost_.data());
        else
            host_kernels::path_tracer_pixel(&launch_settings, &camera_, &scene, pixel, accumulation, squares, rays_.data(), lost_.data());
    });
}

void HostRenderer::launch_light_cache(const kernel::RenderKernelSettings& launch_settings, PixelRange range) {
    const kernel::RenderScene scene = host_render_scene();
    auto* accumulation = reinterpret_cast<brdf::float4*>(film_.accumulation.data());
    auto* squares = reinterpret_cast<brdf::float4*>(film_.squares.data());
    auto* splat = reinterpret_cast<unsigned*>(film_.splat.data());
    const int paths = light_cache_paths(input_.settings);
    const int chunk = 64;
    const auto grid_size = uint32_t(grid_entries_.size());  // 0 without merging
    // one sample index's pool: its light subpaths, their t = 1 splats when `splats`, the offsets
    auto light_pass = [&](const kernel::RenderKernelSettings& settings, int splats, uint32_t* rays, uint32_t* lost) {
        parallel_for(0, paths, chunk, [&](int path) {
            host_kernels::bdpt_cache_light_path(&settings, &camera_, &scene, path, paths, cache_.data(), cache_lengths_.data(), cache_offsets_.data(),
                                                splat, splats, rays, lost);
        });
        host_kernels::bdpt_cache_offsets(cache_offsets_.data(), paths);
        if (settings.bdpt.merge_radius > 0.0f)  // vcm: the pool's hash grid
            host_kernels::vcm_build_grid(&settings, cache_.data(), cache_lengths_.data(), paths, grid_cells_.data(), grid_entries_.data(), grid_size);
    };
    LightCachePasses passes;
    passes.pilot = [&](const kernel::RenderKernelSettings& settings) {
        std::vector<uint32_t> rays(size_t(paths), 0u), lost(size_t(paths), 0u);  // the pilot's rays are no render's
        light_pass(settings, 0, rays.data(), lost.data());
        return int64_t(cache_offsets_[size_t(paths)]);
    };
    passes.light = [&](const kernel::RenderKernelSettings& settings, bool splats) {
        light_pass(settings, splats ? 1 : 0, cache_rays_.data(), cache_lost_.data());
    };
    passes.pixels = [&](const kernel::RenderKernelSettings& settings) {
        parallel_for(range.first, range.first + range.count, std::max(1, input_.settings.width), [&](int pixel) {
            host_kernels::bdpt_cache_pixel(&settings, &camera_, &scene, pixel, cache_.data(), cache_lengths_.data(), cache_offsets_.data(), paths,
                                           input_.settings.bdpt.connections, grid_cells_.data(), grid_entries_.data(),
                                           grid_size, accumulation, squares, rays_.data(), lost_.data());
        });
    };
    launch_light_cache_samples(input_.settings, launch_settings, kernel_settings(kLightCachePilotSample, 1), range.first == 0, &pilot_vertices_,
                               passes);
}

FilmReadback HostRenderer::read_film() const { return film_; }

void HostRenderer::write_film(const FilmReadback& film) { film_ = film; }

void HostRenderer::read_ray_counts(uint64_t* rays, uint64_t* lost) const {
    *rays = *lost = 0;
    for (size_t p = 0; p < rays_.size(); ++p) {
        *rays += rays_[p];
        *lost += lost_[p];
    }
    for (size_t p = 0; p < cache_rays_.size(); ++p) {  // bdpt-cache's light subpaths
        *rays += cache_rays_[p];
        *lost += cache_lost_[p];
    }
}

}  // namespace lab::render
