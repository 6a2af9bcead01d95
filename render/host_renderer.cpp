#include "render/host_renderer.hpp"

#include <atomic>
#include <thread>

#include "render/host_kernels.hpp"

namespace lab::render {

size_t path_state_bytes() { return sizeof(host_kernels::PathState); }

HostRenderer::HostRenderer(RenderInput input, int threads) : Renderer(std::move(input)) {
    threads_ = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    initialize();
}

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
}

void HostRenderer::launch(const kernel::RenderKernelSettings& launch_settings, PixelRange range) {
    const kernel::RenderScene scene = host_render_scene();

    const int pixels = range.first + range.count;
    auto* accumulation = reinterpret_cast<brdf::float4*>(film_.accumulation.data());
    auto* squares = reinterpret_cast<brdf::float4*>(film_.squares.data());
    // The splat buffer holds floats as their bits (kernels/film.h), which the film reads back as floats.
    auto* splat = reinterpret_cast<unsigned*>(film_.splat.data());
    const bool bidirectional = integrator_descriptor(input_.settings.integrator).bidirectional();
    std::atomic<int> next{range.first};
    auto work = [&] {
        const HostSceneScope scene_scope(input_.scene);
        // Rows of pixels at a time: few enough atomics, small enough to balance the threads.
        const int chunk = std::max(1, input_.settings.width);
        for (int begin = next.fetch_add(chunk); begin < pixels; begin = next.fetch_add(chunk))
            for (int pixel = begin; pixel < std::min(pixels, begin + chunk); ++pixel)
                if (bidirectional)
                    host_kernels::bdpt_pixel(&launch_settings, &camera_, &scene, pixel, accumulation, squares, splat, rays_.data(), lost_.data());
                else
                    host_kernels::path_tracer_pixel(&launch_settings, &camera_, &scene, pixel, accumulation, squares, rays_.data(), lost_.data());
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads_; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

FilmReadback HostRenderer::read_film() const { return film_; }

void HostRenderer::write_film(const FilmReadback& film) { film_ = film; }

void HostRenderer::read_ray_counts(uint64_t* rays, uint64_t* lost) const {
    *rays = *lost = 0;
    for (size_t p = 0; p < rays_.size(); ++p) {
        *rays += rays_[p];
        *lost += lost_[p];
    }
}

}  // namespace lab::render
