#include "film/image_stats.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lab::film {

namespace {

std::string size_text(const ImageRgb& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void check(const ImageRgb& image, const char* what) {
    if (!image.valid()) throw std::invalid_argument(std::string(what) + ": the image's sizes (" + size_text(image) + ") do not match its data");
}

}  // namespace

ImageStats image_stats(const ImageRgb& image) {
    check(image, "image_stats");
    ImageStats stats;
    std::array<double, 3> sum{};
    for (size_t p = 0; p < image.rgb.size(); p += 3) {
        const float* c = &image.rgb[p];
        if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
            ++stats.non_finite_pixels;
            continue;
        }
        ++stats.finite_pixels;
        for (int i = 0; i < 3; ++i) sum[size_t(i)] += double(c[i]);
    }
    if (stats.finite_pixels > 0)
        for (int i = 0; i < 3; ++i) stats.mean[size_t(i)] = sum[size_t(i)] / double(stats.finite_pixels);
    return stats;
}

ImageError image_error(const ImageRgb& image, const ImageRgb& reference) {
    check(image, "image_error");
    check(reference, "image_error");
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("image sizes differ: " + size_text(image) + " and " + size_text(reference));
    std::array<double, 3> squared{}, reference_sum{};
    for (size_t p = 0; p < image.rgb.size(); p += 3)
        for (size_t i = 0; i < 3; ++i) {
            const double d = double(image.rgb[p + i]) - double(reference.rgb[p + i]);
            squared[i] += d * d;
            reference_sum[i] += double(reference.rgb[p + i]);
        }
    const double n = double(image.pixel_count());
    ImageError e;
    for (size_t i = 0; i < 3; ++i) {
        e.rmse[i] = std::sqrt(squared[i] / n);
        const double mean = reference_sum[i] / n;
        // IEEE division: a black reference channel gives infinity, or 0 when the image is black there too
        e.relative_rmse[i] = (e.rmse[i] == 0.0) ? 0.0 : e.rmse[i] / std::fabs(mean);
    }
    e.rmse_mean = (e.rmse[0] + e.rmse[1] + e.rmse[2]) / 3.0;
    e.relative_rmse_mean = (e.relative_rmse[0] + e.relative_rmse[1] + e.relative_rmse[2]) / 3.0;
    return e;
}

}  // namespace lab::film
