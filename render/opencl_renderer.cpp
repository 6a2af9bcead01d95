#include "render/opencl_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>

#include "brdf/host/measured_registry.hpp"
#include "kernels/host/material_layout.hpp"
#include "kernels/host/scene_kernel_source.hpp"
#include "render/light_cache.hpp"
#include "render/vcm.hpp"
#include "render/opencl_launch.hpp"

namespace lab::render {

namespace {

// Without -cl-fast-relaxed-math: the kernel shares its BRDF with the host, and NaN guards matter.
constexpr const char* kBuildOptions = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

// The first `count` elements of `data` (one element's bytes when there are none: a buffer cannot be empty).
template <typename T>
opencl::BufferHandle upload(const opencl::Runtime& runtime, const T* data, size_t count) {
    opencl::BufferHandle buffer = runtime.buffer(std::max<size_t>(count, 1) * sizeof(T), CL_MEM_READ_ONLY);
    if (count > 0) runtime.write(buffer, data, count * sizeof(T));
    return buffer;
}
template <typename T>
opencl::BufferHandle upload(const opencl::Runtime& runtime, const std::vector<T>& data) {
    return upload(runtime, data.data(), data.size());
}

}  // namespace

OpenClRenderer::OpenClRenderer(const opencl::Runtime& runtime, RenderInput input)
    : Renderer(std::move(input)), runtime_(runtime), wavefront_driver_(runtime) {
    initialize();
}

// On a CPU only: on a GPU, whose work-items are the SIMD lanes already, eight rays per work-item and
// a launch per step made the path tracer 8 to 20 times slower (docs/render.md, "On a GPU").
bool OpenClRenderer::wavefront() const {
    return integrator_descriptor(input_.settings.integrator).wavefront && input_.settings.opencl.packets && runtime_.device().type == "cpu";
}

int OpenClRenderer::samples_in_flight() const { return wavefront() ? wavefront_slots(input_.settings) : 1; }

std::string OpenClRenderer::device_description() const { return runtime_.device().description(); }

void OpenClRenderer::build_kernel() {
    auto start = std::chrono::steady_clock::now();
    const RenderSettings& s = input_.settings;
    const IntegratorDescriptor& integrator = integrator_descriptor(s.integrator);
    std::string options = kBuildOptions + (s.opencl.extra_build_options.empty() ? "" : " " + s.opencl.extra_build_options);
    // the wavefront's step prefetches environment texels (kernels/path_tracer_wavefront.h); PoCL only
    if (wavefront()) options += " -DWAVEFRONT_PREFETCH";
    // BDPT's private vertex arrays hold exactly the paths its max_depth allows (kernels/bdpt_vertex.h)
    if (integrator.bidirectional()) options += " -DBDPT_MAX_VERTICES=" + std::to_string(bdpt_max_vertices(s));
    // only the samplers of the scene's kinds of light (the marches see none: not the packets'
    // option); the lights keep their kinds once built (Renderer::rebuild_lights changes an
    // environment's rotation and exposure only)
    build_options_ = options + " -DSCENE_LIGHT_TYPES=" + std::to_string(light_type_mask(lights_));
    const std::string entry = s.opencl.program.empty() ? integrator.program : s.opencl.program;
    opencl::Program program = runtime_.build(kernels::assemble_scene_kernel(entry, compiled_), build_options_);
    kernels::check_material_layout(runtime_, program);
    opencl::KernelHandle kernel = program.kernel(integrator.kernel);
    size_t kernel_max = 0;
    opencl::check_cl(clGetKernelWorkGroupInfo(kernel.get(), runtime_.device().device, CL_KERNEL_WORK_GROUP_SIZE, sizeof(kernel_max),
                                              &kernel_max, nullptr),
                     "clGetKernelWorkGroupInfo");
    // kLaunchGranularity (64) work-items unless set (`dtoadq bench breakdown` compares sizes), at
    // most the kernel's maximum
    local_size_ = s.opencl.local_size > 0 ? size_t(s.opencl.local_size) : size_t(kLaunchGranularity);
    while (local_size_ > 1 && local_size_ > kernel_max) local_size_ /= 2;
    program_.emplace(std::move(program));
    first_hit_program_.reset();  // the scene's source or features changed
    if (integrator.light_cache) {
        cache_light_kernel_ = program_->kernel("render_bdpt_cache_light");
        cache_offsets_kernel_ = program_->kernel("render_bdpt_cache_offsets");
        if (integrator.merges) grid_kernel_ = program_->kernel("render_vcm_grid");
    }
    kernel_ = std::move(kernel);
    if (wavefront()) wavefront_driver_.build(*program_, compiled_, options);
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void OpenClRenderer::upload_scene() {
    const ibl::Environment& env = bound_environment();
    // The map's texels and sampling tables (megabytes) stay as they are when the materials, or the
    // environment's rotation and exposure (kernel arguments), change: uploaded once per map.
    if (env.texels().data() != uploaded_texels_ || texels_version() != uploaded_texels_version_) {
        texels_ = upload(runtime_, bound_texels());  // with the blurred backdrop after them, when there is one
        alias_ = upload(runtime_, bound_alias());  // with the emitters' images' after them, when there are any
        uploaded_texels_ = env.texels().data();
        uploaded_texels_version_ = texels_version();
    }
    materials_ = upload(runtime_, compiled_.materials);
    // the BSDF's tables (brdf/bsdf_tables.h) only as far as the scene reads them, and only when that
    // changed: all of them with a measured material, their first part, the energy tables, with an
    // anisotropic one (the viewer's sliders change anisotropy without a new kernel), else one float
    bool measured = false, anisotropic = false;
    for (const brdf::Material& m : compiled_.materials) {
        measured = measured || m.model == BRDF_MODEL_MEASURED;
        anisotropic = anisotropic || m.anisotropic != 0.0f;
    }
    size_t table_floats = measured ? brdf::bsdf_table_data().size() : anisotropic ? size_t(BSDF_TABLES_MEASURED) : 0;
    if (!tables_ || table_floats != table_floats_) {
        tables_ = upload(runtime_, brdf::bsdf_table_data().data(), table_floats);
        table_floats_ = table_floats;
    }
    emission_buffer_ = upload(runtime_, emission_);
    lights_buffer_ = upload(runtime_, lights_.lights);
    light_cdf_ = upload(runtime_, lights_.selection_cdf);
    light_of_slot_ = upload(runtime_, lights_.light_of_slot);
}

void OpenClRenderer::clear_film() {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    if (pixels != film_pixels_) {
        accumulation_ = runtime_.buffer(pixels * 4 * sizeof(float), CL_MEM_READ_WRITE);
        squares_ = runtime_.buffer(pixels * 4 * sizeof(float), CL_MEM_READ_WRITE);
        splat_ = runtime_.buffer(pixels * 3 * sizeof(cl_uint), CL_MEM_READ_WRITE);
        rays_ = runtime_.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
        lost_ = runtime_.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
        film_pixels_ = pixels;
    }
    if (wavefront()) wavefront_driver_.allocate(wavefront_slots(input_.settings), pixels);
    std::vector<float> zeros(pixels * 4, 0.0f);  // 0.0f and 0u share their bits
    runtime_.write(accumulation_, zeros.data(), pixels * 4 * sizeof(float));
    runtime_.write(squares_, zeros.data(), pixels * 4 * sizeof(float));
    runtime_.write(splat_, zeros.data(), pixels * 3 * sizeof(cl_uint));
    runtime_.write(rays_, zeros.data(), pixels * sizeof(cl_uint));
    runtime_.write(lost_, zeros.data(), pixels * sizeof(cl_uint));
    if (integrator_descriptor(input_.settings.integrator).light_cache) {
        const size_t paths = size_t(light_cache_paths(input_.settings));
        cache_ = runtime_.buffer(light_cache_bytes(input_.settings), CL_MEM_READ_WRITE);
        cache_lengths_ = runtime_.buffer(paths * sizeof(cl_int), CL_MEM_READ_WRITE);
        cache_offsets_ = runtime_.buffer((paths + 1) * sizeof(cl_uint), CL_MEM_READ_WRITE);
        cache_rays_ = runtime_.buffer(paths * sizeof(cl_uint), CL_MEM_READ_WRITE);
        cache_lost_ = runtime_.buffer(paths * sizeof(cl_uint), CL_MEM_READ_WRITE);
        std::vector<cl_uint> path_zeros(paths + 1, 0u);
        runtime_.write(cache_offsets_, path_zeros.data(), (paths + 1) * sizeof(cl_uint));
        runtime_.write(cache_rays_, path_zeros.data(), paths * sizeof(cl_uint));
        runtime_.write(cache_lost_, path_zeros.data(), paths * sizeof(cl_uint));
        if (integrator_descriptor(input_.settings.integrator).merges) {
            grid_cells_ = runtime_.buffer((vcm_grid_buckets(input_.settings) + 1) * sizeof(cl_uint), CL_MEM_READ_WRITE);
            grid_entries_ = runtime_.buffer(vcm_grid_buckets(input_.settings) * sizeof(cl_uint), CL_MEM_READ_WRITE);
        }
    }
    pilot_vertices_ = -1;  // the scene, camera or settings may have changed
}

cl_uint OpenClRenderer::bind_render_arguments(const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& launch_settings) const {
    cl_uint a = 0;
    opencl::set_kernel_arg(kernel, a++, launch_settings);
    opencl::set_kernel_arg(kernel, a++, camera_);
    opencl::set_kernel_arg(kernel, a++, bound_environment().map());
    for (const opencl::BufferHandle* b : {&texels_, &alias_, &materials_, &tables_, &emission_buffer_, &lights_buffer_,
                                          &light_cdf_, &light_of_slot_, &accumulation_, &squares_, &splat_, &rays_, &lost_})
        opencl::set_kernel_arg(kernel, a++, *b);
    return a;
}

void OpenClRenderer::launch(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) {
    const int image = input_.settings.width * input_.settings.height;
    if (integrator_descriptor(input_.settings.integrator).light_cache) {
        launch_light_cache(launch_settings, pixels);
        return;
    }
    if (wavefront()) {
        const WavefrontTarget target{&camera_,
                                     [this](const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& settings) {
                                         return bind_render_arguments(kernel, settings);
                                     },
                                     &accumulation_, &squares_, &rays_, &lost_, local_size_, image};
        wavefront_driver_.launch(target, launch_settings, pixels);
    } else {
        bind_render_arguments(kernel_, launch_settings);
        launch_range(runtime_, kernel_, pixels, local_size_, size_t(image));
    }
    runtime_.finish();
}

void OpenClRenderer::launch_light_cache(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) {
    const int image = input_.settings.width * input_.settings.height;
    const cl_int paths = light_cache_paths(input_.settings);
    const bool merges = integrator_descriptor(input_.settings.integrator).merges;
    const cl_uint grid_size = merges ? cl_uint(vcm_grid_buckets(input_.settings)) : 0u;
    // one sample index's pool: its light subpaths, their t = 1 splats when `splats`, the offsets
    auto light_pass = [&](const kernel::RenderKernelSettings& settings, cl_int splats) {
        cl_uint a = bind_render_arguments(cache_light_kernel_, settings);
        // the light subpaths' own ray counters in place of the pixels'
        opencl::set_kernel_arg(cache_light_kernel_, a - 2, cache_rays_);
        opencl::set_kernel_arg(cache_light_kernel_, a - 1, cache_lost_);
        for (const opencl::BufferHandle* b : {&cache_, &cache_lengths_, &cache_offsets_}) opencl::set_kernel_arg(cache_light_kernel_, a++, *b);
        opencl::set_kernel_arg(cache_light_kernel_, a++, paths);
        opencl::set_kernel_arg(cache_light_kernel_, a++, splats);
        launch_range(runtime_, cache_light_kernel_, PixelRange{0, paths}, local_size_, size_t(paths));
        opencl::set_kernel_arg(cache_offsets_kernel_, 0, cache_offsets_);
        opencl::set_kernel_arg(cache_offsets_kernel_, 1, paths);
        runtime_.launch_1d(cache_offsets_kernel_, 1, 1);
        if (merges && settings.bdpt.merge_radius > 0.0f) {  // vcm: the pool's hash grid
            cl_uint g = 0;
            opencl::set_kernel_arg(grid_kernel_, g++, settings);
            for (const opencl::BufferHandle* b : {&cache_, &cache_lengths_}) opencl::set_kernel_arg(grid_kernel_, g++, *b);
            opencl::set_kernel_arg(grid_kernel_, g++, paths);
            for (const opencl::BufferHandle* b : {&grid_cells_, &grid_entries_}) opencl::set_kernel_arg(grid_kernel_, g++, *b);
            opencl::set_kernel_arg(grid_kernel_, g++, grid_size);
            runtime_.launch_1d(grid_kernel_, 1, 1);
        }
    };
    LightCachePasses passes;
    passes.pilot = [&](const kernel::RenderKernelSettings& settings) {
        light_pass(settings, 0);
        std::vector<cl_uint> offsets(size_t(paths) + 1);
        runtime_.read(cache_offsets_, offsets.data(), offsets.size() * sizeof(cl_uint));
        std::vector<cl_uint> zeros(size_t(paths), 0u);  // the pilot's rays are no render's
        runtime_.write(cache_rays_, zeros.data(), zeros.size() * sizeof(cl_uint));
        runtime_.write(cache_lost_, zeros.data(), zeros.size() * sizeof(cl_uint));
        return int64_t(offsets.back());
    };
    passes.light = [&](const kernel::RenderKernelSettings& settings, bool splats) { light_pass(settings, splats ? 1 : 0); };
    passes.pixels = [&](const kernel::RenderKernelSettings& settings) {
        cl_uint a = bind_render_arguments(kernel_, settings);
        for (const opencl::BufferHandle* b : {&cache_, &cache_lengths_, &cache_offsets_}) opencl::set_kernel_arg(kernel_, a++, *b);
        opencl::set_kernel_arg(kernel_, a++, paths);
        opencl::set_kernel_arg(kernel_, a++, cl_int(input_.settings.bdpt.connections));
        // without merging the grid's arguments are any buffers, never read (size 0)
        for (const opencl::BufferHandle* b : {merges ? &grid_cells_ : &cache_offsets_, merges ? &grid_entries_ : &cache_offsets_})
            opencl::set_kernel_arg(kernel_, a++, *b);
        opencl::set_kernel_arg(kernel_, a++, grid_size);
        launch_range(runtime_, kernel_, pixels, local_size_, size_t(image));
    };
    launch_light_cache_samples(input_.settings, launch_settings, kernel_settings(kLightCachePilotSample, 1), pixels.first == 0, &pilot_vertices_,
                               passes);
    runtime_.finish();
}

std::optional<FirstHitAovs> OpenClRenderer::first_hit_aovs(const SampleRanges& ranges, const std::function<bool()>& cancelled) const {
    if (!first_hit_program_) {
        first_hit_program_.emplace(runtime_.build(kernels::assemble_scene_kernel("kernels/first_hit.cl", compiled_), build_options_));
        first_hit_kernel_ = first_hit_program_->kernel("render_first_hits");
    }
    const int image = input_.settings.width * input_.settings.height;
    const size_t bytes = size_t(image) * sizeof(brdf::float4);
    std::vector<brdf::float4> albedo(size_t(image), brdf::float4(0.0f)), normal_depth(size_t(image), brdf::float4(0.0f));
    opencl::BufferHandle albedo_sums = runtime_.buffer(bytes, CL_MEM_READ_WRITE), normal_depth_sums = runtime_.buffer(bytes, CL_MEM_READ_WRITE);
    runtime_.write(albedo_sums, albedo.data(), bytes);
    runtime_.write(normal_depth_sums, normal_depth.data(), bytes);
    std::vector<int> slots(size_t(image), -1);
    opencl::BufferHandle slot_buffer = runtime_.buffer(slots.size() * sizeof(cl_int), CL_MEM_READ_WRITE);
    runtime_.write(slot_buffer, slots.data(), slots.size() * sizeof(cl_int));
    const cl_int slot_sample = ranges.empty() ? -1 : cl_int(ranges.ranges().front().first);
    const int piece = cancelled ? kFirstHitPiece : image;
    for (int begin = 0; begin < image; begin += piece) {
        if (cancelled && cancelled()) return std::nullopt;
        for (const auto& [first, end] : ranges.ranges()) {
            cl_uint a = bind_render_arguments(first_hit_kernel_, kernel_settings(int(first), int(end - first)));
            opencl::set_kernel_arg(first_hit_kernel_, a++, albedo_sums);
            opencl::set_kernel_arg(first_hit_kernel_, a++, normal_depth_sums);
            opencl::set_kernel_arg(first_hit_kernel_, a++, slot_sample);
            opencl::set_kernel_arg(first_hit_kernel_, a++, slot_buffer);
            launch_range(runtime_, first_hit_kernel_, PixelRange{begin, std::min(image - begin, piece)}, local_size_, size_t(image));
            runtime_.finish();
        }
    }
    runtime_.read(albedo_sums, albedo.data(), bytes);
    runtime_.read(normal_depth_sums, normal_depth.data(), bytes);
    runtime_.read(slot_buffer, slots.data(), slots.size() * sizeof(cl_int));
    return first_hit_means(albedo, normal_depth, std::move(slots), ranges.count());
}

std::unique_ptr<DisplayFilter> OpenClRenderer::display_filter() const { return device_display_filter(runtime_.device().id()); }

FilmReadback OpenClRenderer::read_film() const {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    FilmReadback film;
    film.accumulation.resize(pixels * 4);
    film.squares.resize(pixels * 4);
    film.splat.resize(pixels * 3);
    runtime_.read(accumulation_, film.accumulation.data(), film.accumulation.size() * sizeof(float));
    runtime_.read(squares_, film.squares.data(), film.squares.size() * sizeof(float));
    runtime_.read(splat_, film.splat.data(), film.splat.size() * sizeof(float));
    return film;
}

void OpenClRenderer::write_film(const FilmReadback& film) {
    runtime_.write(accumulation_, film.accumulation.data(), film.accumulation.size() * sizeof(float));
    runtime_.write(squares_, film.squares.data(), film.squares.size() * sizeof(float));
    runtime_.write(splat_, film.splat.data(), film.splat.size() * sizeof(float));  // the splat's words hold float bits
}

void OpenClRenderer::read_ray_counts(uint64_t* rays, uint64_t* lost) const {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    std::vector<cl_uint> r(pixels), l(pixels);
    runtime_.read(rays_, r.data(), r.size() * sizeof(cl_uint));
    runtime_.read(lost_, l.data(), l.size() * sizeof(cl_uint));
    *rays = *lost = 0;
    for (size_t p = 0; p < pixels; ++p) {
        *rays += r[p];
        *lost += l[p];
    }
    if (integrator_descriptor(input_.settings.integrator).light_cache) {  // bdpt-cache's light subpaths
        const size_t paths = size_t(light_cache_paths(input_.settings));
        r.resize(paths);
        l.resize(paths);
        runtime_.read(cache_rays_, r.data(), paths * sizeof(cl_uint));
        runtime_.read(cache_lost_, l.data(), paths * sizeof(cl_uint));
        for (size_t p = 0; p < paths; ++p) {
            *rays += r[p];
            *lost += l[p];
        }
    }
}

}  // namespace lab::render
