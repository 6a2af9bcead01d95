// One number per RGB triple for the plots: relative luminance of linear Rec.709 / sRGB primaries.
#pragma once

#include "brdf/brdf.hpp"
#include "common/luminance.hpp"

namespace lab::plots {

inline float luminance(brdf::float3 rgb) { return lab::luminance(rgb.x, rgb.y, rgb.z); }

}  // namespace lab::plots
