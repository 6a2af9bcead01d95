// A renderer on an OpenCL device: the integrator's kernel (kernels/<integrator>.cl) assembled
// around the scene's generated source, built once per set of BRDF features (PoCL caches builds),
// the scene and the film in device buffers.
#pragma once

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

class OpenClRenderer final : public Renderer {
public:
    // Builds the kernel (opencl::KernelBuildError with the mapped log on failure) and uploads the
    // scene. Throws lab::InputError for bad settings or camera before anything is built.
    OpenClRenderer(const opencl::Runtime& runtime, RenderInput input);

    std::string device_description() const override;

    // The path tracer's wavefront (kernels/path_tracer_wavefront.h), when RenderSettings::packets
    // and the device is a CPU: its marches run eight rays per work-item on the vector lanes.
    bool wavefront() const;

private:
    void build_kernel() override;
    void upload_scene() override;
    void clear_film() override;
    void launch(const kernel::RenderKernelSettings& k, PixelRange pixels) override;
    FilmReadback read_film() const override;
    void write_film(const FilmReadback& film) override;
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override;

    const opencl::Runtime& runtime_;
    std::optional<opencl::Program> program_;
    opencl::KernelHandle kernel_;
    // The wavefront's step kernel, packet kernel (kernels/march_packets.cl) and per-path buffers:
    // k.sample_count samples in flight, one path per pixel and sample (the whole image when more
    // than one).
    void launch_wavefront_samples(const kernel::RenderKernelSettings& k, PixelRange pixels);
    cl_uint bind_render_arguments(const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& k) const;
    void launch_range(const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total) const;
    std::optional<opencl::Program> packet_program_;
    std::string packet_source_, packet_options_;  // what packet_program_ was built from
    opencl::KernelHandle step_kernel_, resolve_kernel_, march_rays_;
    opencl::BufferHandle states_, path_rays_, shadow_rays_, ray_marches_, shadow_marches_, unfinished_;
    opencl::BufferHandle path_radiance_, path_ray_counts_, path_lost_counts_;  // per path, several samples in flight
    int wavefront_slots_ = 0;  // samples in flight the buffers hold
    int stride_ = 0;           // entries of each ray array: the paths rounded up to a whole packet
    size_t local_size_ = 64;
    opencl::BufferHandle texels_, alias_, materials_, emission_buffer_, lights_buffer_, light_cdf_, light_of_slot_;
    opencl::BufferHandle measured_;  // brdf::measured_table_data(), or one float for a scene without measured materials
    size_t measured_floats_ = 0;
    opencl::BufferHandle accumulation_, splat_, rays_, lost_;
    size_t film_pixels_ = 0;  // the size the film buffers were made for
    const brdf::float4* uploaded_texels_ = nullptr;  // the environment texels texels_ holds
};

}  // namespace lab::render
