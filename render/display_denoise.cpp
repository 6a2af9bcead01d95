#include "render/display_denoise.hpp"

#include <cmath>

namespace lab::render {

film::DenoiseGuide denoise_guide(const FirstHitAovs& aovs, const film::ImageRgb& variance) {
    film::DenoiseGuide guide;
    guide.albedo = aovs.albedo;
    guide.normal = aovs.normal;
    guide.depth = aovs.depth;
    guide.variance.resize(variance.pixel_count());
    for (size_t p = 0; p < guide.variance.size(); ++p) {
        const float* v = variance.rgb.data() + 3 * p;
        const float sigma = 0.2126f * std::sqrt(v[0]) + 0.7152f * std::sqrt(v[1]) + 0.0722f * std::sqrt(v[2]);
        if (!std::isfinite(sigma)) {
            guide.variance.clear();
            break;
        }
        guide.variance[p] = sigma * sigma;
    }
    return guide;
}

film::ImageRgb denoised(const film::ImageRgb& radiance, const film::DenoiseGuide& guide, DisplayFilter& filter,
                        const film::FilterCancelled& cancelled, const film::DenoiseOptions& options) {
    film::AtrousBuffers buffers = film::demodulate(radiance, guide);
    if (!filter.passes(&buffers, options, cancelled)) return film::ImageRgb();
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
