#include "render/display_denoise.hpp"

namespace lab::render {

film::DenoiseGuide denoise_guide(const FirstHitAovs& aovs) {
    film::DenoiseGuide guide;
    guide.albedo = aovs.albedo;
    guide.normal = aovs.normal;
    guide.depth = aovs.depth;
    return guide;
}

film::ImageRgb denoised(const film::ImageRgb& radiance, const film::DenoiseGuide& guide, const Renderer& renderer,
                        const film::DenoiseOptions& options) {
    film::AtrousBuffers buffers = film::demodulate(radiance, guide);
    renderer.display_filter_passes(&buffers, options);
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
