// A renderer on an OpenCL device: the integrator's kernel (kernels/<integrator>.cl) assembled
// around the scene's generated source, built once per set of BRDF features (PoCL caches builds),
// the scene and the film in device buffers.
#pragma once

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"
#include "render/wavefront_driver.hpp"

namespace lab::render {

class OpenClRenderer final : public Renderer {
public:
    // Builds the kernel (opencl::KernelBuildError with the mapped log on failure) and uploads the
    // scene. Throws lab::InputError for bad settings or camera before anything is built.
    OpenClRenderer(const opencl::Runtime& runtime, RenderInput input);

    std::string device_description() const override;

    // The path tracer's wavefront (kernels/path_tracer_wavefront.h), when OpenClTuning::packets
    // and the device is a CPU: its marches run eight rays per work-item on the vector lanes.
    bool wavefront() const;
    // Samples of every pixel the wavefront keeps in flight (OpenClTuning::wavefront_paths); 1
    // without the wavefront.
    int samples_in_flight() const;

    // Tells `observer` of every launch of the wavefront from now on (WavefrontDriver::observe_launches).
    void observe_wavefront_launches(WavefrontLaunchObserver* observer) { wavefront_driver_.observe_launches(observer); }

    // The options the integrator's program was last built with: among them the scene's kinds of
    // light (-DSCENE_LIGHT_TYPES, kernels/lights/light_selection.h).
    const std::string& build_options() const { return build_options_; }

    // The first-hit AOVs by render_first_hits (kernels/first_hit.cl), a program built at the first
    // call after each build of the integrator's, so a render without AOVs never compiles it.
    using Renderer::first_hit_aovs;
    std::optional<FirstHitAovs> first_hit_aovs(const SampleRanges& ranges, const std::function<bool()>& cancelled) const override;
    // On this renderer's device, in a context of its own.
    std::unique_ptr<DisplayFilter> display_filter() const override;

private:
    void build_kernel() override;
    void upload_scene() override;
    void clear_film() override;
    void launch(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) override;
    FilmReadback read_film() const override;
    void write_film(const FilmReadback& film) override;
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override;

    const opencl::Runtime& runtime_;
    std::optional<opencl::Program> program_;
    std::string build_options_;
    opencl::KernelHandle kernel_;
    mutable std::optional<opencl::Program> first_hit_program_;  // built by first_hit_aovs
    mutable opencl::KernelHandle first_hit_kernel_;
    // Arguments 0 .. 15, which every render kernel takes (kernels/path_tracer.cl); returns the next index.
    cl_uint bind_render_arguments(const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& launch_settings) const;
    WavefrontDriver wavefront_driver_;  // used when wavefront()
    size_t local_size_ = 64;
    opencl::BufferHandle texels_, alias_, materials_, emission_buffer_, lights_buffer_, light_cdf_, light_of_slot_;
    opencl::BufferHandle tables_;  // brdf::bsdf_table_data(), its energy tables alone, or one float (upload_scene)
    size_t table_floats_ = 0;
    opencl::BufferHandle accumulation_, squares_, splat_, rays_, lost_;
    size_t film_pixels_ = 0;  // the size the film buffers were made for
    // bdpt-cache (kernels/bdpt.cl, kernels/bdpt_cache.h): its light pass and offsets kernels, one sample index's
    // light subpaths (vertices, lengths, offsets), their rays, and the pilot pool's connectable
    // vertices (render/light_cache.hpp), -1 until it is traced
    void launch_light_cache(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels);
    opencl::KernelHandle cache_light_kernel_, cache_offsets_kernel_;
    opencl::BufferHandle cache_, cache_lengths_, cache_offsets_, cache_rays_, cache_lost_;
    // vcm: the hash grid's kernel and buffers (kernels/hash_grid.h)
    opencl::KernelHandle grid_kernel_;
    opencl::BufferHandle grid_cells_, grid_entries_;
    int64_t pilot_vertices_ = -1;
    const brdf::float4* uploaded_texels_ = nullptr;  // the environment texels texels_ holds
    uint64_t uploaded_texels_version_ = 0;           // and Renderer::texels_version() when uploaded
};

}  // namespace lab::render
