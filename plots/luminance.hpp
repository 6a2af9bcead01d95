// One number per RGB triple for the plots: relative luminance of linear Rec.709 / sRGB primaries.
#pragma once

#include "brdf/brdf.hpp"

namespace lab::plots {

inline float luminance(brdf::float3 rgb) { return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z; }

}  // namespace lab::plots
