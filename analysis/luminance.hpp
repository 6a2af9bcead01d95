// One number per RGB triple for the lobe data, the charts and the viewer: relative luminance of linear Rec.709 / sRGB primaries.
#pragma once

#include "brdf/brdf.hpp"
#include "common/luminance.hpp"

namespace lab::analysis {

inline float luminance(brdf::float3 rgb) { return lab::luminance(rgb.x, rgb.y, rgb.z); }

}  // namespace lab::analysis
