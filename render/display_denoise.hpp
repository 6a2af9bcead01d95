// `--denoise on` for `render` and `preview`: the image shown denoised (film/denoise.hpp), guided by
// the render's first-hit AOVs, with the raw image kept beside it as the EXR layer noisy.R/G/B, as
// Blender keeps its noisy pass, so nothing rendered is lost. On the OpenCL device when the render
// ran there.
#pragma once

#include <vector>

#include "film/denoise.hpp"
#include "film/image_output.hpp"
#include "kernels/host/denoise_device.hpp"
#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// The filter's guide from the render's first-hit AOVs (the variance left to be estimated from the image).
film::DenoiseGuide denoise_guide(const FirstHitAovs& aovs);

// The denoised image: its passes on `device` when given, else on the host.
film::ImageRgb denoised(const film::ImageRgb& radiance, const film::DenoiseGuide& guide, const kernels::DeviceDenoiser* device,
                        const film::DenoiseOptions& options = {});
// The same guided by the AOVs, on `runtime`'s device when given (the filter built there), else on the host.
film::ImageRgb denoised(const film::ImageRgb& radiance, const FirstHitAovs& aovs, const opencl::Runtime* runtime);

// The raw image as EXR channels noisy.R, noisy.G, noisy.B.
std::vector<film::ImageChannel> noisy_channels(const film::ImageRgb& radiance);

}  // namespace lab::render
