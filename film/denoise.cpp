#include "film/denoise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/parallel_for.hpp"
#include "single_source/host_vocabulary.hpp"

namespace lab::film {

// The host's steps around the passes (demodulate, estimate_variance, remodulate) run a row or a strip
// of columns a task on every core: at 1 spp they are a third of the filter's time, and the passes on
// the device use every core too.

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

// SVGF's spatial estimate (demodulate's comment): the sample variance of the luminance over the
// 7 x 7 pixels around each pixel that show a surface. The counts and sums are box sums, a row's
// then a column's, kept as running sums: a few adds a pixel whatever the window.
void estimate_variance(AtrousBuffers* b) {
    const int radius = 3, w = b->width, h = b->height;
    const size_t row_length = 3 * size_t(w);
    // the moments 1, l, l^2 of a pixel on a surface (0 elsewhere), summed along its row's window
    std::vector<double> rows(3 * b->illumination.size());
    parallel_for(h, hardware_threads(), [&](int y) {
        const size_t first = size_t(y) * size_t(w);
        double* out = rows.data() + 3 * first;
        std::vector<double> moments(3 * size_t(w), 0.0);
        for (int x = 0; x < w; ++x)
            if (b->guide[first + size_t(x)][3] > 0.0f) {
                const std::array<float, 4>& c = b->illumination[first + size_t(x)];
                const double l = atrous::atrous_luminance(c[0], c[1], c[2]);
                moments[3 * size_t(x)] = 1.0;
                moments[3 * size_t(x) + 1] = l;
                moments[3 * size_t(x) + 2] = l * l;
            }
        double sum[3] = {0.0, 0.0, 0.0};
        for (int x = 0; x < std::min(radius, w); ++x)
            for (int m = 0; m < 3; ++m) sum[m] += moments[3 * size_t(x) + size_t(m)];
        for (int x = 0; x < w; ++x)
            for (int m = 0; m < 3; ++m) {
                if (x + radius < w) sum[m] += moments[3 * size_t(x + radius) + size_t(m)];
                if (x - radius - 1 >= 0) sum[m] -= moments[3 * size_t(x - radius - 1) + size_t(m)];
                out[3 * x + m] = sum[m];
            }
    });
    // down each strip of columns, a row at a time so that the memory is read in order
    const int strip = 64, strips = (w + strip - 1) / strip;
    parallel_for(strips, hardware_threads(), [&](int s) {
        const int x0 = s * strip, x1 = std::min(w, x0 + strip);
        std::vector<double> column(3 * size_t(x1 - x0), 0.0);
        const auto add_row = [&](int y, double sign) {
            const double* r = rows.data() + size_t(y) * row_length + 3 * size_t(x0);
            for (size_t k = 0; k < column.size(); ++k) column[k] += sign * r[k];
        };
        for (int y = 0; y < std::min(radius, h); ++y) add_row(y, 1.0);
        for (int y = 0; y < h; ++y) {
            if (y + radius < h) add_row(y + radius, 1.0);
            if (y - radius - 1 >= 0) add_row(y - radius - 1, -1.0);
            for (int x = x0; x < x1; ++x) {
                const size_t p = size_t(y) * size_t(w) + size_t(x);
                const double* sums = column.data() + 3 * size_t(x - x0);
                // the count is whole, so its running sum is exact; the moments' cancellation is a double's
                const double count = std::round(sums[0]), mean = count > 0.0 ? sums[1] / count : 0.0;
                b->illumination[p][3] = b->guide[p][3] > 0.0f && count > 1.0
                                            ? float(std::max(0.0, (sums[2] / count - mean * mean) * count / (count - 1.0)))
                                            : 0.0f;
            }
        }
    });
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
    parallel_for(b.height, hardware_threads(), [&](int y) {
        for (size_t p = size_t(y) * size_t(b.width); p < size_t(y + 1) * size_t(b.width); ++p) {
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
    });
    if (guide.variance.empty()) estimate_variance(&b);
    return b;
}

ImageRgb remodulate(const AtrousBuffers& filtered, const DenoiseGuide& guide) {
    ImageRgb out(filtered.width, filtered.height);
    parallel_for(out.height, hardware_threads(), [&](int y) {
        for (size_t p = size_t(y) * size_t(out.width); p < size_t(y + 1) * size_t(out.width); ++p)
            for (size_t c = 0; c < 3; ++c) out.rgb[3 * p + c] = filtered.illumination[p][c] * demodulator(guide.albedo.rgb[3 * p + c]);
    });
    return out;
}

bool atrous_passes(AtrousBuffers* b, const DenoiseOptions& options, const FilterCancelled& cancelled) {
    std::vector<std::array<float, 4>> next(b->illumination.size());
    for (int i = 0; i < options.passes; ++i) {
        if (cancelled && cancelled()) return false;
        const atrous::AtrousPass pass =
            atrous::atrous_pass(b->width, b->height, 1 << i, options.sigma_normal, options.sigma_depth, options.sigma_luminance);
        for (int y = 0; y < b->height; ++y)
            for (int x = 0; x < b->width; ++x)
                atrous::atrous_pixel(&pass, as_floats(b->illumination), as_floats(b->guide), x, y,
                                     next[size_t(y) * size_t(b->width) + size_t(x)].data());
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
