// Denoising a progressive render for display: the edge-avoiding a-trous filter of
// film/denoise_atrous.h, guided by the first hit's albedo, normal and depth and by the pixels'
// variance, on the illumination (radiance / albedo) so that texture stays sharp. A display filter:
// the film is never changed by it.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "film/image.hpp"

namespace lab::film {

// What the render core writes beside radiance for the filter, one entry per pixel in the image's order.
struct DenoiseGuide {
    ImageRgb albedo;                 // the first hit's albedo (0 where the camera ray hit nothing)
    ImageRgb normal;                 // the first hit's unit shading normal
    std::vector<float> depth;        // the camera ray's distance to the first hit; <= 0 where it hit nothing
    std::vector<float> variance;     // the variance of the pixel's mean radiance (luminance); empty: estimated from the image
};

struct DenoiseOptions {
    int passes = 4;                  // widths 1, 2, 4, 8 of the 3 x 3 taps: a footprint of 31 pixels
    float sigma_normal = 16.0f;
    float sigma_depth = 2.0f;
    float sigma_luminance = 4.0f;
};

// The filter's working buffers: per pixel the illumination (radiance / albedo) with the variance of
// its luminance, and the guide (normal, depth), as float4 each: the layout of film/denoise_atrous.h,
// the same on the host (glm::vec4) and in an OpenCL buffer. (Four planes instead, one 8-float load
// per channel on the device's lanes, were slower: 24 streams of rows per pass against 6.)
struct AtrousBuffers {
    int width = 0, height = 0;
    std::vector<std::array<float, 4>> illumination, guide;
};

// The radiance divided by the albedo (a channel under 1e-3 is left as it is) and the guide packed
// (normals made unit: a pixel's mean normal is shorter at an edge). Without a variance in the guide,
// each pixel's is estimated from the image, as SVGF does before it has a history: the spread of the
// illumination's luminance over the 7 x 7 pixels around it on the same surface (normals within 25
// degrees, depths within 5 %), which is the variance of a pixel's mean where the image is flat.
// Throws std::invalid_argument when the guide's sizes differ from the image's.
AtrousBuffers demodulate(const ImageRgb& radiance, const DenoiseGuide& guide);
// The filtered illumination times the albedo again.
ImageRgb remodulate(const AtrousBuffers& filtered, const DenoiseGuide& guide);
// Asked between passes whether to give up (a filter on a thread of its own whose image is no longer
// wanted); empty: never.
using FilterCancelled = std::function<bool()>;

// options.passes passes of widths 1, 2, 4, ... on the host's threads (this one). False: `cancelled`
// said so between two passes, and the buffers hold a partly filtered image.
bool atrous_passes(AtrousBuffers* buffers, const DenoiseOptions& options, const FilterCancelled& cancelled = {});

// The denoised image, on the host: demodulate, the passes, remodulate.
ImageRgb denoise(const ImageRgb& radiance, const DenoiseGuide& guide, const DenoiseOptions& options = {});

}  // namespace lab::film
