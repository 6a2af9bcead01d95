#include "film/denoise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "single_source/host_vocabulary.hpp"

namespace lab::film {

// The filter's single-source pass, compiled for the host here.
namespace atrous {
using namespace single_source;
#include "film/denoise_atrous.h"
}  // namespace atrous

namespace {

static_assert(sizeof(std::array<float, 4>) == 4 * sizeof(float), "the buffers' pixels must be four packed floats, as the device's");

// An albedo channel small enough to divide noise up unboundedly: such a pixel is filtered as it is.
constexpr float kMinAlbedo = 1e-3f;

float demodulator(float albedo) { return albedo > kMinAlbedo ? albedo : 1.0f; }

const float* as_floats(const std::vector<std::array<float, 4>>& v) { return v.front().data(); }

// SVGF's spatial estimate (demodulate's comment): 7 x 7, the same surface only.
void estimate_variance(AtrousBuffers* b) {
    const int radius = 3;
    const float same_normal = 0.906f;  // cos 25 degrees
    const float same_depth = 0.05f;
    std::vector<float> variance(b->illumination.size(), 0.0f);
    for (int y = 0; y < b->height; ++y)
        for (int x = 0; x < b->width; ++x) {
            const size_t p = size_t(y) * size_t(b->width) + size_t(x);
            const std::array<float, 4>& gp = b->guide[p];
            if (gp[3] <= 0.0f) continue;
            double sum = 0.0, sum_sq = 0.0;
            int count = 0;
            for (int j = -radius; j <= radius; ++j)
                for (int i = -radius; i <= radius; ++i) {
                    const int qx = x + i, qy = y + j;
                    if (qx < 0 || qy < 0 || qx >= b->width || qy >= b->height) continue;
                    const size_t q = size_t(qy) * size_t(b->width) + size_t(qx);
                    const std::array<float, 4>& gq = b->guide[q];
                    if (gq[3] <= 0.0f || gp[0] * gq[0] + gp[1] * gq[1] + gp[2] * gq[2] < same_normal ||
                        std::fabs(gq[3] - gp[3]) > same_depth * gp[3])
                        continue;
                    const std::array<float, 4>& c = b->illumination[q];
                    const double l = atrous::atrous_luminance(c[0], c[1], c[2]);
                    sum += l;
                    sum_sq += l * l;
                    ++count;
                }
            const double mean = sum / count;  // count >= 1: the pixel itself
            variance[p] = count > 1 ? float(std::max(0.0, (sum_sq / count - mean * mean) * count / (count - 1))) : 0.0f;
        }
    for (size_t p = 0; p < variance.size(); ++p) b->illumination[p][3] = variance[p];
}

}  // namespace

AtrousBuffers demodulate(const ImageRgb& radiance, const DenoiseGuide& guide) {
    const size_t n = radiance.pixel_count();
    if (!radiance.valid() || guide.albedo.width != radiance.width || guide.albedo.height != radiance.height ||
        guide.normal.width != radiance.width || guide.normal.height != radiance.height || guide.depth.size() != n ||
        (!guide.variance.empty() && guide.variance.size() != n))
        throw std::invalid_argument("denoise: the guide's buffers are not of the image's size");
    AtrousBuffers b;
    b.width = radiance.width;
    b.height = radiance.height;
    b.illumination.resize(n);
    b.guide.resize(n);
    for (size_t p = 0; p < n; ++p) {
        const float* c = radiance.rgb.data() + 3 * p;
        const float* a = guide.albedo.rgb.data() + 3 * p;
        const float* nn = guide.normal.rgb.data() + 3 * p;
        const float albedo[3] = {demodulator(a[0]), demodulator(a[1]), demodulator(a[2])};
        const float albedo_luminance = atrous::atrous_luminance(albedo[0], albedo[1], albedo[2]);
        // the variance of the illumination's luminance, the albedo taken as exact
        const float variance = guide.variance.empty() ? 0.0f : guide.variance[p] / (albedo_luminance * albedo_luminance);
        b.illumination[p] = {c[0] / albedo[0], c[1] / albedo[1], c[2] / albedo[2], variance};
        const float length = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
        const float inv = length > 0.0f ? 1.0f / length : 0.0f;
        b.guide[p] = {nn[0] * inv, nn[1] * inv, nn[2] * inv, guide.depth[p]};
    }
    if (guide.variance.empty()) estimate_variance(&b);
    return b;
}

ImageRgb remodulate(const AtrousBuffers& filtered, const DenoiseGuide& guide) {
    ImageRgb out(filtered.width, filtered.height);
    for (size_t p = 0; p < out.pixel_count(); ++p)
        for (size_t c = 0; c < 3; ++c) out.rgb[3 * p + c] = filtered.illumination[p][c] * demodulator(guide.albedo.rgb[3 * p + c]);
    return out;
}

bool atrous_passes(AtrousBuffers* b, const DenoiseOptions& options, const FilterCancelled& cancelled) {
    std::vector<std::array<float, 4>> next(b->illumination.size());
    for (int i = 0; i < options.passes; ++i) {
        if (cancelled && cancelled()) return false;
        const atrous::AtrousPass pass =
            atrous::atrous_pass(b->width, b->height, 1 << i, options.sigma_normal, options.sigma_depth, options.sigma_luminance);
        for (int y = 0; y < b->height; ++y)
            for (int x = 0; x < b->width; ++x) {
                atrous::atrous_pixel(&pass, as_floats(b->illumination), as_floats(b->guide), x, y,
                                     next[size_t(y) * size_t(b->width) + size_t(x)].data());
            }
        b->illumination.swap(next);
    }
    return true;
}

ImageRgb denoise(const ImageRgb& radiance, const DenoiseGuide& guide, const DenoiseOptions& options) {
    AtrousBuffers buffers = demodulate(radiance, guide);
    atrous_passes(&buffers, options);
    return remodulate(buffers, guide);
}

}  // namespace lab::film
