#include "render/display_denoise.hpp"

#include "kernels/host/denoise_device.hpp"

namespace lab::render {

film::ImageRgb denoised(const film::ImageRgb& radiance, const FirstHitAovs& aovs, const opencl::Runtime* runtime) {
    film::DenoiseGuide guide;
    guide.albedo = aovs.albedo;
    guide.normal = aovs.normal;
    guide.depth = aovs.depth;
    film::AtrousBuffers buffers = film::demodulate(radiance, guide);
    const film::DenoiseOptions options;
    if (runtime)
        kernels::DeviceDenoiser(*runtime).passes(&buffers, options);
    else
        film::atrous_passes(&buffers, options);
    return film::remodulate(buffers, guide);
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
