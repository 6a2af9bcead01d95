#include "kernels/host/denoise_device.hpp"

#include <string>

#include "kernels/host/brdf_batch.hpp"
#include "kernels/host/embedded_sources.hpp"

namespace lab::kernels {

namespace {

constexpr size_t kLocalSize = 64;

}  // namespace

DeviceDenoiser::DeviceDenoiser(const opencl::Runtime& runtime)
    : runtime_(runtime), program_(build_embedded(runtime, "kernels/denoise.cl", std::string(BrdfBatch::kBuildOptions) + " -DSDF_LANES=8")), pass_(program_.kernel("denoise_atrous_pass")) {}

bool DeviceDenoiser::passes(film::AtrousBuffers* b, const film::DenoiseOptions& options, const film::FilterCancelled& cancelled) const {
    const size_t n = b->illumination.size(), bytes = n * sizeof(b->illumination[0]);
    opencl::BufferHandle guide = runtime_.buffer(bytes, CL_MEM_READ_ONLY);
    opencl::BufferHandle ping = runtime_.buffer(bytes, CL_MEM_READ_WRITE), pong = runtime_.buffer(bytes, CL_MEM_READ_WRITE);
    runtime_.write(guide, b->guide.data(), bytes);
    runtime_.write(ping, b->illumination.data(), bytes);
    for (int i = 0; i < options.passes; ++i) {
        if (cancelled) {
            runtime_.finish();
            if (cancelled()) return false;
        }
        const opencl::BufferHandle& from = i % 2 == 0 ? ping : pong;
        const opencl::BufferHandle& to = i % 2 == 0 ? pong : ping;
        opencl::set_kernel_args(pass_, b->width, b->height, 1 << i, options.sigma_normal, options.sigma_depth, options.sigma_luminance, from, guide, to);
        // a work-item per eight pixels of a row (kernels/denoise.cl)
        runtime_.launch_1d(pass_, size_t((b->width + 7) / 8) * size_t(b->height), kLocalSize);
    }
    runtime_.read(options.passes % 2 == 0 ? ping : pong, b->illumination.data(), bytes);
    return true;
}

}  // namespace lab::kernels
