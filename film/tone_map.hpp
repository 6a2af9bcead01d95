// From linear radiance to the 8-bit sRGB of a PNG: exposure, a tone curve, the sRGB transfer
// function, rounding. The EXR output skips all of this and keeps the linear values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "film/image.hpp"

namespace lab::film {

enum class ToneMap { Aces, Reinhard, Clamp };

// "aces", "reinhard", "clamp". Anything else throws lab::InputError("--tonemap", "", ...).
ToneMap parse_tone_map(const std::string& text);
const char* tone_map_name(ToneMap tone_map);

// Relative luminance of linear Rec.709 / sRGB primaries (ITU-R BT.709, the Y row of its RGB->XYZ).
float luminance(float r, float g, float b);

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (blog post): a rational fit of the ACES
// reference rendering transform, x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0, 1].
// Applied to each channel.
float aces_narkowicz(float x);

// sRGB transfer function, IEC 61966-2-1: linear [0, 1] -> encoded [0, 1], and its inverse.
// The two pieces meet at linear 0.0031308 <-> encoded 0.04045.
float srgb_encode(float linear);
float srgb_decode(float encoded);

// Encoded [0, 1] -> 0..255, rounded to nearest; values outside [0, 1] are clamped.
uint8_t quantize8(float encoded);

// quantize8(srgb_encode(display)) for a finite display value, the same code for every float,
// found among the 255 values where the code steps up instead of through a pow: what turns
// an image into its 8-bit sRGB bytes (to_srgb8) about twice as fast: 4096 buckets of [0, 1] and one
// comparison with the step in the bucket.
uint8_t srgb8_code(float display);

// One pixel through exposure and the tone curve: rgb * 2^exposure_stops, negatives set to 0, then
//   Aces:     aces_narkowicz per channel;
//   Reinhard: Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3,
//             L_d = L / (1 + L) on the luminance L, applied as the scale L_d / L to the colour
//             (so hue is kept), then each channel clamped to 1 (a saturated colour can exceed it);
//   Clamp:    each channel clamped to [0, 1].
// The result is linear display values in [0, 1], not yet sRGB encoded. Inputs must be finite.
void tone_map_pixel(const float in[3], ToneMap tone_map, float exposure_stops, float out[3]);

// The 8-bit sRGB value of every pixel (3 bytes per pixel, same order as ImageRgb::rgb).
// A pixel with any non-finite channel becomes magenta (255, 0, 255) so it shows.
std::vector<uint8_t> to_srgb8(const ImageRgb& image, ToneMap tone_map, float exposure_stops);

}  // namespace lab::film
