// The same integrators compiled as C++ and run on the host's threads, one pixel at a time, with the
// same random numbers as the OpenCL build (kernels/path_tracer.h and the headers it includes are
// single source). The scene's distance field is the host interpreter's (scene/interpreter.hpp),
// which evaluates the same sdf/ headers the compiled source calls. For stepping through a path in
// a debugger, running it under AddressSanitizer and UBSan, and checking the device against it.
#pragma once

#include <functional>

#include "render/renderer.hpp"

namespace lab::render::host_kernels {
struct PathVertex;  // kernels/bdpt_vertex.h, compiled in render/host_kernels.hpp
}

namespace lab::render {

// Bytes of a path's state between the OpenCL wavefront's steps (kernels/path_tracer.h, PathState):
// four-byte members only, so the host's layout, where the struct is compiled, is the kernels'.
size_t path_state_bytes();

class HostRenderer final : public Renderer {
public:
    // threads: 0 uses every hardware thread.
    explicit HostRenderer(RenderInput input, int threads = 0);
    ~HostRenderer() override;

    std::string device_description() const override;

private:
    void build_kernel() override {}  // nothing to build: the integrator is compiled into the binary
    void upload_scene() override {}  // the scene is read where it is
    void clear_film() override;
    void launch(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) override;
    FilmReadback read_film() const override;
    void write_film(const FilmReadback& film) override;
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override;

    // The light-vertex cache's passes (kernels/bdpt_cache.h), one sample index at a time.
    void launch_light_cache(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels);
    // `count` items, `chunk` at a time, on every thread, each in the scene's scope.
    void parallel_for(int first, int end, int chunk, const std::function<void(int)>& item) const;

    int threads_ = 1;
    FilmReadback film_;
    std::vector<uint32_t> rays_, lost_;
    // bdpt-cache: the vertices, lengths and offsets of one sample's light subpaths, their rays, and
    // the pilot pool's connectable vertices (render/light_cache.hpp), -1 until it is traced
    std::vector<host_kernels::PathVertex> cache_;
    std::vector<int> cache_lengths_;
    std::vector<uint32_t> cache_offsets_, cache_rays_, cache_lost_;
    // vcm: the hash grid over one sample's light vertices (kernels/hash_grid.h); empty without merging
    std::vector<uint32_t> grid_cells_, grid_entries_;
    int64_t pilot_vertices_ = -1;
};

}  // namespace lab::render
