// `--denoise on` for `render`, `preview` and the viewer: the image shown denoised
// (film/denoise.hpp), guided by the render's first-hit AOVs, its passes run where the render runs
// (Renderer::display_filter). `render` and `preview` keep the raw image beside it as the EXR
// layer noisy.R/G/B, as Blender keeps its noisy pass, so nothing rendered is lost.
#pragma once

#include <vector>

#include "film/denoise.hpp"
#include "film/image_output.hpp"
#include "render/display_filter.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// The filter's guide: the render's first-hit AOVs, and the variance of each pixel's mean luminance
// from the film's per-channel variances (Renderer::variance), (sum_c w_c sigma_c)^2: the channels
// taken as fully correlated, as one path carries all three, which bounds the luminance's variance
// from above. Where any pixel has no variance (NaN: fewer than 2 samples), the variance is left
// out, for film::demodulate to estimate from the image.
film::DenoiseGuide denoise_guide(const FirstHitAovs& aovs, const film::ImageRgb& variance);

// The denoised image, its passes by `filter` (Renderer::display_filter: on the render's device);
// an empty image when `cancelled` stopped it.
film::ImageRgb denoised(const film::ImageRgb& radiance, const film::DenoiseGuide& guide, DisplayFilter& filter,
                        const film::FilterCancelled& cancelled, const film::DenoiseOptions& options = {});

// The raw image as EXR channels noisy.R, noisy.G, noisy.B.
std::vector<film::ImageChannel> noisy_channels(const film::ImageRgb& radiance);

}  // namespace lab::render
