// The image-based-lighting preview on OpenCL: one compiled scene (kernels/preview.cl with the
// scene's generated source) under one environment, rendered progressively: every add_samples()
// call adds samples to every pixel's running sum, and image() is the mean so far.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "film/image.hpp"
#include "ibl/environment.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "scene/scene.hpp"

namespace lab::ibl {

// How the environment is sampled (kernels/preview.cl): the BSDF only, the environment only
// (next-event estimation), or both combined by multiple importance sampling.
enum class IblSampling { brdf, env, mis };
enum class NormalMethod { tetrahedral, central, analytic };

// Parse the command-line words; errors are lab::InputError naming `option`.
IblSampling parse_ibl_sampling(const std::string& text, const std::string& option = "--ibl-sampling");
NormalMethod parse_normal_method(const std::string& text, const std::string& option = "--normals");
const char* ibl_sampling_name(IblSampling sampling);
const char* normal_method_name(NormalMethod method);

// The largest image side the preview renders (and the command line accepts).
constexpr int kMaxImageSide = 16384;

struct PreviewSettings {
    int width = 512, height = 512;
    int max_depth = 16;      // scattering events per path
    int roulette_depth = 3;  // Russian roulette from this many events on
    IblSampling sampling = IblSampling::mis;
    NormalMethod normals = NormalMethod::tetrahedral;
    float normal_step = 5e-4f;     // finite-difference step, scene units
    float over_relaxation = 1.0f;  // 1: plain sphere tracing
    int max_steps = 1024;
    float max_distance = 100.0f;
    uint64_t seed = 0;
    std::string extra_build_options;  // appended to the OpenCL build options (e.g. a -D forcing a cold build)
};

// Throws lab::InputError naming the option for a size, depth, step count or over-relaxation out
// of range. The renderer calls it too; callers call it first to fail before any loading.
void check_preview_settings(const PreviewSettings& settings);

// What the preview needs of a compiled scene (scene/): its kernel source assembled around
// kernels/preview.cl, its material slots in kernel order, and its camera and Lipschitz bound.
struct PreviewScene {
    std::string file;  // the scene file, for messages
    opencl::AssembledSource kernel_source;
    std::vector<brdf::Material> materials;
    std::vector<std::array<float, 4>> emission;  // per slot: radiance, and 1 for an emitter's slot
    float lipschitz = 1.0f;
    scene::Camera camera;
    std::vector<std::string> warnings;  // the compiler's (a Lipschitz bound above 1, a broken bound)
};

struct PreviewStatistics {
    int samples_per_pixel = 0;
    double render_seconds = 0.0;  // in add_samples(), kernels and transfers
    uint64_t paths = 0, rays = 0;
    uint64_t lost_rays = 0;          // marches that ran out of steps
    uint64_t nonfinite_samples = 0;  // paths whose radiance was NaN or infinite: left out and counted
    double paths_per_second() const { return render_seconds > 0.0 ? double(paths) / render_seconds : 0.0; }
    double rays_per_second() const { return render_seconds > 0.0 ? double(rays) / render_seconds : 0.0; }
};

class PreviewRenderer {
public:
    // Builds the kernel (KernelBuildError with the mapped log on failure) and uploads the scene's
    // materials and the environment. Throws lab::InputError for an unsupported camera or bad sizes.
    PreviewRenderer(const opencl::Runtime& runtime, const PreviewScene& scene, const Environment& environment,
                    const PreviewSettings& settings);

    double build_seconds() const { return build_seconds_; }

    // Renders `count` more samples per pixel, in launches of samples_per_launch() each; blocks.
    void add_samples(int count);
    // Samples per pixel of one launch: enough work to amortise a launch, little enough that a
    // progress bar moves. Defaults to 1; may be set to any value >= 1.
    int samples_per_launch() const { return samples_per_launch_; }
    void set_samples_per_launch(int n) { samples_per_launch_ = n < 1 ? 1 : n; }

    // The mean radiance so far (all zeros before the first sample); non-finite samples excluded.
    film::ImageRgb image() const;
    PreviewStatistics statistics() const;
    const PreviewSettings& settings() const { return settings_; }

private:
    void set_arguments();
    void launch(int first_sample, int count);

    const opencl::Runtime& runtime_;
    PreviewSettings settings_;
    double build_seconds_ = 0.0;
    opencl::Program program_;
    opencl::KernelHandle kernel_;
    std::vector<unsigned char> kernel_settings_;  // the kernel's PreviewSettings struct, as bytes
    opencl::BufferHandle texels_, marginal_, conditional_, materials_, emission_, accumulation_, rays_, lost_;
    int samples_ = 0;
    int samples_per_launch_ = 1;
    double render_seconds_ = 0.0;
    size_t local_size_ = 64;
};

}  // namespace lab::ibl
