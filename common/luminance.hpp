// Relative luminance of linear Rec.709 / sRGB primaries (ITU-R BT.709, the Y row of its RGB to XYZ
// matrix): the one number per colour that plots, tone mapping and environment sampling weigh by.
#pragma once

namespace lab {

template <typename T>
constexpr T luminance(T r, T g, T b) {
    return T(0.2126) * r + T(0.7152) * g + T(0.0722) * b;
}

}  // namespace lab
