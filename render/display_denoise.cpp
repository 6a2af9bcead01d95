#include "render/display_denoise.hpp"

namespace lab::render {

film::DenoiseGuide denoise_guide(const FirstHitAovs& aovs) {
    film::DenoiseGuide guide;
    guide.albedo = aovs.albedo;
    guide.normal = aovs.normal;
    guide.depth = aovs.depth;
    return guide;
}

film::ImageRgb denoised(const film::ImageRgb& radiance, const film::DenoiseGuide& guide, const kernels::DeviceDenoiser* device,
                        const film::DenoiseOptions& options) {
    film::AtrousBuffers buffers = film::demodulate(radiance, guide);
    if (device)
        device->passes(&buffers, options);
    else
        film::atrous_passes(&buffers, options);
    return film::remodulate(buffers, guide);
}

film::ImageRgb denoised(const film::ImageRgb& radiance, const FirstHitAovs& aovs, const opencl::Runtime* runtime) {
    if (!runtime) return denoised(radiance, denoise_guide(aovs), nullptr);
    const kernels::DeviceDenoiser device(*runtime);
    return denoised(radiance, denoise_guide(aovs), &device);
}

std::vector<film::ImageChannel> noisy_channels(const film::ImageRgb& radiance) {
    std::vector<film::ImageChannel> channels;
    for (int c = 0; c < 3; ++c) {
        film::ImageChannel channel{std::string("noisy.") + "RGB"[c], std::vector<float>(radiance.pixel_count())};
        for (size_t p = 0; p < radiance.pixel_count(); ++p) channel.values[p] = radiance.rgb[3 * p + size_t(c)];
        channels.push_back(std::move(channel));
    }
    return channels;
}

}  // namespace lab::render
