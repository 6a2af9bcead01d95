#include "render/opencl_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "brdf/host/measured_registry.hpp"
#include "kernels/host/material_layout.hpp"
#include "kernels/host/scene_kernel_source.hpp"
#include "render/host_renderer.hpp"

namespace lab::render {

namespace {

// Without -cl-fast-relaxed-math: the kernel shares its BRDF with the host, and NaN guards matter.
constexpr const char* kBuildOptions = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

// lt is bdpt's kernel with a strategy mask (RenderKernelSettings.strategies), not a kernel of its own.
const char* kernel_file(Integrator integrator) { return integrator == Integrator::pt ? "kernels/path_tracer.cl" : "kernels/bdpt.cl"; }

const char* kernel_name(Integrator integrator) { return integrator == Integrator::pt ? "render_pt" : "render_bdpt"; }

template <typename T>
opencl::BufferHandle upload(const opencl::Runtime& runtime, const std::vector<T>& data) {
    opencl::BufferHandle buffer = runtime.buffer(std::max<size_t>(data.size(), 1) * sizeof(T), CL_MEM_READ_ONLY);
    if (!data.empty()) runtime.write(buffer, data.data(), data.size() * sizeof(T));
    return buffer;
}

// Paths the wavefront keeps in flight unless RenderSettings::wavefront_paths says otherwise: a
// step and a march of a launch cost some fifty microseconds of launching and waiting whatever their
// size, and at 128 x 128 one sample of a simple scene takes only a few milliseconds.
constexpr int kWavefrontPaths = 1 << 16;

// Samples of every pixel the wavefront keeps in flight: about kWavefrontPaths paths, at least one sample.
int wavefront_slots(const RenderSettings& s) {
    const int64_t pixels = int64_t(s.width) * s.height;
    const int64_t paths = s.wavefront_paths > 0 ? s.wavefront_paths : kWavefrontPaths;
    return int(std::max<int64_t>(1, paths / pixels));
}

}  // namespace

OpenClRenderer::OpenClRenderer(const opencl::Runtime& runtime, RenderInput input) : Renderer(std::move(input)), runtime_(runtime) {
    initialize();
}

// On a CPU only: on a GPU, whose work-items are the SIMD lanes already, eight rays per work-item and
// a launch per step made the path tracer 8 to 20 times slower (docs/render.md, "On a GPU").
bool OpenClRenderer::wavefront() const {
    return input_.settings.integrator == Integrator::pt && input_.settings.packets && runtime_.device().type == "cpu";
}

void OpenClRenderer::time_wavefront_launches(bool on) {
    time_launches_ = on;
    launch_times_ = WavefrontLaunchTimes{};
}

int OpenClRenderer::samples_in_flight() const { return wavefront() ? wavefront_slots(input_.settings) : 1; }

std::string OpenClRenderer::device_description() const { return runtime_.device().description(); }

void OpenClRenderer::build_kernel() {
    auto start = std::chrono::steady_clock::now();
    const RenderSettings& s = input_.settings;
    std::string options = kBuildOptions + (s.extra_build_options.empty() ? "" : " " + s.extra_build_options);
    // the wavefront's step prefetches environment texels (kernels/path_tracer_wavefront.h); PoCL only
    if (wavefront()) options += " -DWAVEFRONT_PREFETCH";
    // BDPT's private vertex arrays hold exactly the paths its max_depth allows (kernels/bdpt_vertex.h)
    if (s.integrator != Integrator::pt) options += " -DBDPT_MAX_VERTICES=" + std::to_string(bdpt_max_vertices(s));
    // only the samplers of the scene's kinds of light (the marches see none: not the packets'
    // option); the lights keep their kinds once built (Renderer::rebuild_lights changes an
    // environment's rotation and exposure only)
    build_options_ = options + " -DSCENE_LIGHT_TYPES=" + std::to_string(light_type_mask(lights_));
    opencl::Program program = runtime_.build(kernels::assemble_scene_kernel(kernel_file(s.integrator), compiled_), build_options_);
    kernels::check_material_layout(runtime_, program);
    opencl::KernelHandle kernel = program.kernel(kernel_name(s.integrator));
    size_t kernel_max = 0;
    opencl::check_cl(clGetKernelWorkGroupInfo(kernel.get(), runtime_.device().device, CL_KERNEL_WORK_GROUP_SIZE, sizeof(kernel_max),
                                              &kernel_max, nullptr),
                     "clGetKernelWorkGroupInfo");
    // kLaunchGranularity (64) work-items unless set (`dtoadq bench breakdown` compares sizes), at
    // most the kernel's maximum
    local_size_ = s.local_size > 0 ? size_t(s.local_size) : size_t(kLaunchGranularity);
    while (local_size_ > 1 && local_size_ > kernel_max) local_size_ /= 2;
    program_.emplace(std::move(program));
    kernel_ = std::move(kernel);
    if (wavefront()) {
        first_step_kernel_ = program_->kernel("render_pt_first_step");
        step_kernel_ = program_->kernel("render_pt_step");
        camera_kernel_ = program_->kernel("render_pt_camera");
        resolve_kernel_ = program_->kernel("render_pt_resolve");
        // The marches see only the geometry (scene/generated.h): a change of materials, which
        // rebuilds the step kernel, keeps this program.
        opencl::AssembledSource packets = kernels::assemble_scene_kernel("kernels/march_packets.cl", compiled_);
        std::string packet_options = options + " -DSDF_LANES=8";
        if (!packet_program_ || packets.text != packet_source_ || packet_options != packet_options_) {
            packet_program_.emplace(runtime_.build(packets, packet_options));
            march_rays_ = packet_program_->kernel("march_rays");
            march_camera_rays_ = packet_program_->kernel("march_camera_rays");
            packet_source_ = std::move(packets.text);
            packet_options_ = std::move(packet_options);
        }
    }
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void OpenClRenderer::upload_scene() {
    const ibl::Environment& env = bound_environment();
    // The map's texels and sampling tables (megabytes) stay as they are when the materials, or the
    // environment's rotation and exposure (kernel arguments), change: uploaded once per map.
    if (env.texels().data() != uploaded_texels_) {
        texels_ = upload(runtime_, env.texels());
        alias_ = upload(runtime_, env.alias());
        uploaded_texels_ = env.texels().data();
    }
    materials_ = upload(runtime_, compiled_.materials);
    // the measured tables only for a scene that has a measured material, and only when they changed
    bool measured = false;
    for (const brdf::Material& m : compiled_.materials) measured = measured || m.model == BRDF_MODEL_MEASURED;
    size_t measured_floats = measured ? brdf::measured_table_data().size() : 0;
    if (!measured_ || measured_floats != measured_floats_) {
        measured_ = upload(runtime_, measured ? brdf::measured_table_data() : std::vector<float>());
        measured_floats_ = measured_floats;
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
        splat_ = runtime_.buffer(pixels * 3 * sizeof(cl_uint), CL_MEM_READ_WRITE);
        rays_ = runtime_.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
        lost_ = runtime_.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
        film_pixels_ = pixels;
    }
    const int slots = wavefront() ? wavefront_slots(input_.settings) : 0;
    if (wavefront() && (slots != wavefront_slots_ || size_t(stride_) < size_t(slots) * pixels)) {
        wavefront_slots_ = slots;
        const size_t paths = size_t(slots) * pixels;
        stride_ = int((paths + 7) / 8 * 8);
        const size_t n = size_t(stride_);
        states_ = runtime_.buffer(n * path_state_bytes(), CL_MEM_READ_WRITE);
        // the padding past the image holds no ray (kernels/ray_march.h), so that its lanes idle
        std::vector<float> no_rays(n * RAY_FIELDS, NO_RAY);
        path_rays_ = runtime_.buffer(no_rays.size() * sizeof(float), CL_MEM_READ_WRITE);
        shadow_rays_ = runtime_.buffer(no_rays.size() * sizeof(float), CL_MEM_READ_WRITE);
        runtime_.write(path_rays_, no_rays.data(), no_rays.size() * sizeof(float));
        runtime_.write(shadow_rays_, no_rays.data(), no_rays.size() * sizeof(float));
        ray_marches_ = runtime_.buffer(n * sizeof(kernel::RayMarch), CL_MEM_READ_WRITE);
        shadow_marches_ = runtime_.buffer(n * sizeof(kernel::RayMarch), CL_MEM_READ_WRITE);
        camera_rngs_ = runtime_.buffer(n * 4 * sizeof(cl_uint), CL_MEM_READ_WRITE);
        unfinished_ = runtime_.buffer(2 * sizeof(cl_uint), CL_MEM_READ_WRITE);
        path_radiance_ = runtime_.buffer(n * 4 * sizeof(float), CL_MEM_READ_WRITE);
        path_ray_counts_ = runtime_.buffer(n * sizeof(cl_uint), CL_MEM_READ_WRITE);
        path_lost_counts_ = runtime_.buffer(n * sizeof(cl_uint), CL_MEM_READ_WRITE);
    }
    std::vector<float> zeros(pixels * 4, 0.0f);  // 0.0f and 0u share their bits
    runtime_.write(accumulation_, zeros.data(), pixels * 4 * sizeof(float));
    runtime_.write(splat_, zeros.data(), pixels * 3 * sizeof(cl_uint));
    runtime_.write(rays_, zeros.data(), pixels * sizeof(cl_uint));
    runtime_.write(lost_, zeros.data(), pixels * sizeof(cl_uint));
}

// Work-items range.first .. range.first + range.count - 1 of `kernel`, of `total` for the image. The
// range starts at a multiple of its granularity and spans whole granules unless it ends the image,
// where the kernels stop by themselves. A work-group size set above the granularity (bench breakdown's study) would round a
// partial range up into work-items of the next launch: such a launch takes the largest halving of
// it that fits the range.
void OpenClRenderer::launch_range(const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total) const {
    const bool ends_image = size_t(range.first) + size_t(range.count) >= total;
    while (local > 1 && (size_t(range.first) % local != 0 || (!ends_image && size_t(range.count) % local != 0))) local /= 2;
    runtime_.launch_1d(kernel, size_t(range.count), local, size_t(range.first));
}

// Arguments 0 .. 14, which every render kernel takes (kernels/path_tracer.cl); returns the next index.
cl_uint OpenClRenderer::bind_render_arguments(const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& k) const {
    cl_uint a = 0;
    opencl::set_kernel_arg(kernel, a++, k);
    opencl::set_kernel_arg(kernel, a++, camera_);
    opencl::set_kernel_arg(kernel, a++, bound_environment().map());
    for (const opencl::BufferHandle* b : {&texels_, &alias_, &materials_, &measured_, &emission_buffer_, &lights_buffer_,
                                          &light_cdf_, &light_of_slot_, &accumulation_, &splat_, &rays_, &lost_})
        opencl::set_kernel_arg(kernel, a++, *b);
    return a;
}

void OpenClRenderer::launch(const kernel::RenderKernelSettings& k, PixelRange pixels) {
    if (wavefront()) {
        // up to wavefront_slots_ samples at a time, and only one for a part of the image: the
        // buffers hold that many paths of every pixel
        const bool whole = pixels.first == 0 && pixels.count == input_.settings.width * input_.settings.height;
        kernel::RenderKernelSettings batch = k;
        for (int i = 0; i < k.sample_count; i += batch.sample_count) {
            batch.first_sample = k.first_sample + i;
            batch.sample_count = whole ? std::min(wavefront_slots_, k.sample_count - i) : 1;
            launch_wavefront_samples(batch, pixels);
        }
    } else {
        bind_render_arguments(kernel_, k);
        launch_range(kernel_, pixels, local_size_, size_t(input_.settings.width) * size_t(input_.settings.height));
    }
    runtime_.finish();
}

// kernels/path_tracer_wavefront.h's loop: steps, and the packets of their rays and shadow rays,
// until no path has anything left to march; then, with several samples in flight, the resolve that
// adds them to the film in sample order. Per step the host waits once, for the step's two flags (a
// ray left, a shadow ray left), and launches one march of what is left.
void OpenClRenderer::launch_wavefront_samples(const kernel::RenderKernelSettings& k, PixelRange pixels) {
    const int image = input_.settings.width * input_.settings.height;
    const int slots = k.sample_count;
    // path slot * image + pixel: with one sample, the range's pixels; with several, all of them
    const PixelRange paths = slots == 1 ? pixels : PixelRange{0, slots * image};
    const int path_count = slots * image;
    // MARCH_RAYS_PER_ITEM (64) paths a work-item: a range of whole granules of 64 paths
    static_assert(MARCH_RAYS_PER_ITEM == kLaunchGranularity, "a packet work-item marches one granule");
    const int granules = (path_count + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM;
    const PixelRange packets{paths.first / MARCH_RAYS_PER_ITEM, (paths.count + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM};
    // march_rays' work-items: the rays' granules, then the shadow rays'
    const PixelRange shadow_packets{granules + packets.first, packets.count};
    const size_t packet_local = 1, packet_total = 2 * size_t(granules);
    // with timing on: the time since `start` added to `kind` (the host has waited for the launch)
    using Clock = std::chrono::steady_clock;
    auto count = [](WavefrontLaunchTimes::Kind& kind, Clock::time_point start) {
        kind.seconds += std::chrono::duration<double>(Clock::now() - start).count();
        kind.launches += 1;
    };
    // the step kernels' arguments (kernels/path_tracer.cl, WAVEFRONT_KERNEL_ARGUMENTS)
    auto bind_step = [&](const opencl::KernelHandle& step) {
        cl_uint a = bind_render_arguments(step, k);
        opencl::set_kernel_arg(step, a++, stride_);
        for (const opencl::BufferHandle* b : {&states_, &path_rays_, &shadow_rays_, &ray_marches_, &shadow_marches_, &unfinished_})
            opencl::set_kernel_arg(step, a++, *b);
        opencl::set_kernel_arg(step, a++, slots);
        for (const opencl::BufferHandle* b : {&path_radiance_, &path_ray_counts_, &path_lost_counts_, &camera_rngs_})
            opencl::set_kernel_arg(step, a++, *b);
    };
    // Iteration 0, the camera rays: a pinhole's are begun on the packets' lanes and marched in one
    // launch (march_camera_rays); a thin lens's by the camera step, one path per work-item, then
    // marched. Every path has one, so the host need not ask.
    const Clock::time_point camera_start = Clock::now();
    if (camera_.lens_radius > 0.0f) {
        bind_step(camera_kernel_);
        launch_range(camera_kernel_, paths, local_size_, size_t(path_count));
        if (time_launches_) {
            runtime_.finish();
            count(launch_times_.camera_steps, camera_start);
        }
        const Clock::time_point march_start = Clock::now();
        opencl::set_kernel_args(march_rays_, k, path_count, stride_, path_rays_, ray_marches_, shadow_rays_, shadow_marches_);
        launch_range(march_rays_, packets, packet_local, packet_total);
        if (time_launches_) {
            runtime_.finish();
            count(launch_times_.camera_marches, march_start);
        }
    } else {
        opencl::set_kernel_args(march_camera_rays_, k, camera_, path_count, stride_, path_rays_, camera_rngs_, ray_marches_);
        launch_range(march_camera_rays_, packets, packet_local, size_t(granules));
        if (time_launches_) {
            runtime_.finish();
            count(launch_times_.camera_marches, camera_start);
        }
    }
    for (int iteration = 1;; ++iteration) {
        const Clock::time_point step_start = Clock::now();
        // max_depth scattering events, and the last shadow ray one step later
        if (iteration > k.max_depth + 3) throw std::logic_error("path tracer wavefront: paths still unfinished after max_depth + 3 steps");
        runtime_.zero(unfinished_, 2 * sizeof(cl_uint));
        const opencl::KernelHandle& step = iteration == 1 ? first_step_kernel_ : step_kernel_;
        bind_step(step);
        launch_range(step, paths, local_size_, size_t(path_count));
        cl_uint unfinished[2] = {0, 0};
        runtime_.read(unfinished_, unfinished, sizeof(unfinished));  // blocking: the step is done
        const bool last = unfinished[0] == 0 && unfinished[1] == 0;
        if (time_launches_) count(last ? launch_times_.last_steps : launch_times_.scatter_steps, step_start);
        if (last) break;
        const Clock::time_point march_start = Clock::now();
        opencl::set_kernel_args(march_rays_, k, path_count, stride_, path_rays_, ray_marches_, shadow_rays_, shadow_marches_);
        if (unfinished[0] != 0 && unfinished[1] != 0 && packets.count == granules)
            launch_range(march_rays_, PixelRange{0, 2 * granules}, packet_local, packet_total);  // both, in one launch
        else {
            if (unfinished[0] != 0) launch_range(march_rays_, packets, packet_local, packet_total);
            if (unfinished[1] != 0) launch_range(march_rays_, shadow_packets, packet_local, packet_total);
        }
        if (time_launches_) {
            runtime_.finish();
            count(launch_times_.marches, march_start);
        }
    }
    if (slots > 1) {
        const Clock::time_point resolve_start = Clock::now();
        opencl::set_kernel_args(resolve_kernel_, image, slots, accumulation_, rays_, lost_, path_radiance_, path_ray_counts_,
                                path_lost_counts_);
        launch_range(resolve_kernel_, PixelRange{0, image}, local_size_, size_t(image));
        if (time_launches_) {
            runtime_.finish();
            count(launch_times_.resolves, resolve_start);
        }
    }
}

FilmReadback OpenClRenderer::read_film() const {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    FilmReadback film;
    film.accumulation.resize(pixels * 4);
    film.splat.resize(pixels * 3);
    runtime_.read(accumulation_, film.accumulation.data(), film.accumulation.size() * sizeof(float));
    runtime_.read(splat_, film.splat.data(), film.splat.size() * sizeof(float));
    return film;
}

void OpenClRenderer::write_film(const FilmReadback& film) {
    runtime_.write(accumulation_, film.accumulation.data(), film.accumulation.size() * sizeof(float));
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
}

}  // namespace lab::render
