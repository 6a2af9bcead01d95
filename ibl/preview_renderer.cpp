#include "ibl/preview_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "common/input_error.hpp"
#include "opencl/material_layout.hpp"

#include "render/camera_setup.hpp"

namespace preview_kernel {
using namespace brdf;
#include "kernels/preview_settings.h"
}  // namespace preview_kernel

namespace lab::ibl {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Without -cl-fast-relaxed-math: the kernel shares its BRDF with the host, and NaN guards matter.
constexpr const char* kBuildOptions = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

// Images beyond 2^26 pixels are refused up front: the kernel counts pixels in an int.
constexpr long kMaxPixels = 1L << 26;

template <typename Enum, size_t N>
Enum parse_word(const std::string& text, const std::string& option, const std::pair<const char*, Enum> (&words)[N]) {
    std::string known;
    for (const auto& [word, value] : words) {
        if (text == word) return value;
        known += std::string(known.empty() ? "" : ", ") + word;
    }
    throw InputError(option, "", "unknown value \"" + text + "\" (" + known + ")");
}

constexpr std::pair<const char*, IblSampling> kSamplingWords[] = {
    {"brdf", IblSampling::brdf}, {"env", IblSampling::env}, {"mis", IblSampling::mis}};
constexpr std::pair<const char*, NormalMethod> kNormalWords[] = {
    {"tetrahedral", NormalMethod::tetrahedral}, {"central", NormalMethod::central}, {"analytic", NormalMethod::analytic}};

int strategy_code(IblSampling s) {
    switch (s) {
        case IblSampling::brdf: return IBL_SAMPLING_BRDF;
        case IblSampling::env: return IBL_SAMPLING_ENV;
        case IblSampling::mis: break;
    }
    return IBL_SAMPLING_MIS;
}

// sdf/normals.h numbers the methods in this order.
int normal_code(NormalMethod m) { return m == NormalMethod::tetrahedral ? 0 : (m == NormalMethod::central ? 1 : 2); }

template <typename T>
opencl::BufferHandle upload(const opencl::Runtime& runtime, const std::vector<T>& data) {
    opencl::BufferHandle buffer = runtime.buffer(std::max<size_t>(data.size(), 1) * sizeof(T), CL_MEM_READ_ONLY);
    if (!data.empty()) runtime.write(buffer, data.data(), data.size() * sizeof(T));
    return buffer;
}

}  // namespace

IblSampling parse_ibl_sampling(const std::string& text, const std::string& option) { return parse_word(text, option, kSamplingWords); }
NormalMethod parse_normal_method(const std::string& text, const std::string& option) { return parse_word(text, option, kNormalWords); }

const char* ibl_sampling_name(IblSampling sampling) {
    for (const auto& [word, value] : kSamplingWords)
        if (value == sampling) return word;
    return "?";
}

const char* normal_method_name(NormalMethod method) {
    for (const auto& [word, value] : kNormalWords)
        if (value == method) return word;
    return "?";
}

void check_preview_settings(const PreviewSettings& settings) {
    if (settings.width < 1 || settings.height < 1 || settings.width > kMaxImageSide || settings.height > kMaxImageSide ||
        long(settings.width) * settings.height > kMaxPixels)
        throw InputError("--size", "", std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                                           " is outside 1x1 .. " + std::to_string(kMaxImageSide) + " a side and 2^26 pixels");
    if (settings.max_depth < 0 || settings.max_depth > 1024)
        throw InputError("--max-depth", "", "must be in [0, 1024], got " + std::to_string(settings.max_depth));
    if (settings.max_steps < 1 || settings.max_steps > 1 << 20)
        throw InputError("--max-steps", "", "must be in [1, 1048576], got " + std::to_string(settings.max_steps));
    if (!(settings.over_relaxation >= 1.0f && settings.over_relaxation <= 2.0f))
        throw InputError("--over-relaxation", "", "must be in [1, 2]");
}

namespace {

const PreviewSettings& checked(const PreviewSettings& settings) {
    check_preview_settings(settings);
    return settings;
}

// Everything about the scene is checked before the (slow) build.
opencl::Program build_program(const opencl::Runtime& runtime, const PreviewScene& scene, const PreviewSettings& settings,
                              double* seconds) {
    if (scene.materials.empty() || scene.materials.size() != scene.emission.size())
        throw std::invalid_argument("PreviewScene: one emission entry per material slot, at least one slot");
    render::make_camera(scene.camera, settings.width, settings.height, scene.file);
    Clock::time_point start = Clock::now();
    std::string options = kBuildOptions + (settings.extra_build_options.empty() ? "" : " " + settings.extra_build_options);
    opencl::Program program = runtime.build(scene.kernel_source, options);
    opencl::check_material_layout(runtime, program);
    *seconds = seconds_since(start);
    return program;
}

}  // namespace

PreviewRenderer::PreviewRenderer(const opencl::Runtime& runtime, const PreviewScene& scene, const Environment& environment,
                                 const PreviewSettings& settings)
    : runtime_(runtime),
      settings_(checked(settings)),
      program_(build_program(runtime, scene, settings, &build_seconds_)),
      kernel_(program_.kernel("preview_render")) {
    ::kernel::Camera camera = render::make_camera(scene.camera, settings.width, settings.height, scene.file);
    size_t kernel_max = 0;
    opencl::check_cl(clGetKernelWorkGroupInfo(kernel_.get(), runtime.device().device, CL_KERNEL_WORK_GROUP_SIZE, sizeof(kernel_max),
                                              &kernel_max, nullptr),
                     "clGetKernelWorkGroupInfo");
    while (local_size_ > 1 && local_size_ > kernel_max) local_size_ /= 2;

    preview_kernel::PreviewKernelSettings k{};
    k.max_depth = settings.max_depth;
    k.roulette_depth = settings.roulette_depth;
    k.strategy = strategy_code(settings.sampling);
    k.normal_method = normal_code(settings.normals);
    k.normal_step = settings.normal_step;
    k.seed_lo = unsigned(settings.seed & 0xffffffffu);
    k.seed_hi = unsigned(settings.seed >> 32);
    k.max_steps = settings.max_steps;
    k.max_distance = settings.max_distance;
    k.over_relaxation = settings.over_relaxation;
    k.lipschitz = std::max(scene.lipschitz, 1.0f);
    kernel_settings_.resize(sizeof(k));
    std::memcpy(kernel_settings_.data(), &k, sizeof(k));

    texels_ = upload(runtime, environment.texels());
    marginal_ = upload(runtime, environment.marginal_cdf());
    conditional_ = upload(runtime, environment.conditional_cdf());
    materials_ = upload(runtime, scene.materials);
    emission_ = upload(runtime, scene.emission);
    size_t pixels = size_t(settings.width) * size_t(settings.height);
    accumulation_ = runtime.buffer(pixels * 4 * sizeof(float), CL_MEM_READ_WRITE);
    rays_ = runtime.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
    lost_ = runtime.buffer(pixels * sizeof(cl_uint), CL_MEM_READ_WRITE);
    std::vector<float> zeros(pixels * 4, 0.0f);
    runtime.write(accumulation_, zeros.data(), pixels * 4 * sizeof(float));
    runtime.write(rays_, zeros.data(), pixels * sizeof(cl_uint));
    runtime.write(lost_, zeros.data(), pixels * sizeof(cl_uint));

    opencl::set_kernel_arg(kernel_, 1, camera);
    opencl::set_kernel_arg(kernel_, 2, environment.map());
    opencl::set_kernel_arg(kernel_, 3, texels_);
    opencl::set_kernel_arg(kernel_, 4, marginal_);
    opencl::set_kernel_arg(kernel_, 5, conditional_);
    opencl::set_kernel_arg(kernel_, 6, materials_);
    opencl::set_kernel_arg(kernel_, 7, emission_);
    opencl::set_kernel_arg(kernel_, 8, accumulation_);
    opencl::set_kernel_arg(kernel_, 9, rays_);
    opencl::set_kernel_arg(kernel_, 10, lost_);
}

void PreviewRenderer::launch(int first_sample, int count) {
    preview_kernel::PreviewKernelSettings k;
    std::memcpy(&k, kernel_settings_.data(), sizeof(k));
    k.first_sample = first_sample;
    k.sample_count = count;
    opencl::set_kernel_arg(kernel_, 0, k);
    runtime_.launch_1d(kernel_, size_t(settings_.width) * size_t(settings_.height), local_size_);
}

void PreviewRenderer::add_samples(int count) {
    Clock::time_point start = Clock::now();
    while (count > 0) {
        int n = std::min(count, samples_per_launch_);
        launch(samples_, n);
        runtime_.finish();
        samples_ += n;
        count -= n;
    }
    render_seconds_ += seconds_since(start);
}

film::ImageRgb PreviewRenderer::image() const {
    size_t pixels = size_t(settings_.width) * size_t(settings_.height);
    std::vector<float> sum(pixels * 4);
    runtime_.read(accumulation_, sum.data(), sum.size() * sizeof(float));
    film::ImageRgb out(settings_.width, settings_.height);
    for (size_t p = 0; p < pixels; ++p) {
        double finite = double(samples_) - double(sum[4 * p + 3]);
        for (int c = 0; c < 3; ++c) out.rgb[3 * p + size_t(c)] = finite > 0.0 ? float(sum[4 * p + size_t(c)] / finite) : 0.0f;
    }
    return out;
}

PreviewStatistics PreviewRenderer::statistics() const {
    size_t pixels = size_t(settings_.width) * size_t(settings_.height);
    std::vector<float> sum(pixels * 4);
    std::vector<cl_uint> rays(pixels), lost(pixels);
    runtime_.read(accumulation_, sum.data(), sum.size() * sizeof(float));
    runtime_.read(rays_, rays.data(), rays.size() * sizeof(cl_uint));
    runtime_.read(lost_, lost.data(), lost.size() * sizeof(cl_uint));
    PreviewStatistics s;
    s.samples_per_pixel = samples_;
    s.render_seconds = render_seconds_;
    s.paths = uint64_t(samples_) * pixels;
    for (size_t p = 0; p < pixels; ++p) {
        s.rays += rays[p];
        s.lost_rays += lost[p];
        s.nonfinite_samples += uint64_t(sum[4 * p + 3]);
    }
    return s;
}

}  // namespace lab::ibl
