// Numbers about images: per-channel means, the count of non-finite pixels, and the error of a
// render against a reference (root mean square error, absolute and relative to the reference).
#pragma once

#include <array>
#include <cstddef>

#include "film/image.hpp"

namespace lab::film {

struct ImageStats {
    std::array<double, 3> mean{};   // per channel, over the finite pixels only (0 when there are none)
    size_t finite_pixels = 0;
    size_t non_finite_pixels = 0;   // pixels with a NaN or an infinity in any channel
};

ImageStats image_stats(const ImageRgb& image);

struct ImageError {
    std::array<double, 3> rmse{};           // per channel: sqrt(mean over pixels of (image - reference)^2)
    double rmse_mean = 0.0;                 // the mean of the three channels' RMSE
    std::array<double, 3> relative_rmse{};  // rmse[c] / (mean of the reference's channel c); infinite for a black channel
    double relative_rmse_mean = 0.0;        // the mean of the three
};

// Over every pixel: a non-finite pixel in either image makes the result non-finite (a NaN in a
// render is a bug to be seen, not averaged away). Images of different sizes are
// std::invalid_argument ("image sizes differ: 4x3 and 5x3").
ImageError image_error(const ImageRgb& image, const ImageRgb& reference);

}  // namespace lab::film
