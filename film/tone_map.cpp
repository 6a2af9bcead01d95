#include "film/tone_map.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <cmath>
#include <stdexcept>

#include "common/input_error.hpp"
#include "common/luminance.hpp"

namespace lab::film {

namespace {

// Display white is reached long before this (ACES at x ~ 7.2, Reinhard's scale is ~1/L); the bound
// only keeps x * x and 1 + L finite when a large value meets a large exposure.
constexpr float kLargestInput = 1e15f;

float clamp01(float x) { return std::min(std::max(x, 0.0f), 1.0f); }

}  // namespace

ToneMap parse_tone_map(const std::string& text) {
    if (text == "aces") return ToneMap::Aces;
    if (text == "reinhard") return ToneMap::Reinhard;
    if (text == "clamp") return ToneMap::Clamp;
    throw InputError("--tonemap", "", "unknown tone map \"" + text + "\" (aces, reinhard, clamp)");
}

const char* tone_map_name(ToneMap tone_map) {
    switch (tone_map) {
        case ToneMap::Aces: return "aces";
        case ToneMap::Reinhard: return "reinhard";
        case ToneMap::Clamp: return "clamp";
    }
    return "?";
}

float luminance(float r, float g, float b) { return lab::luminance(r, g, b); }

float aces_narkowicz(float x) {
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    x = std::min(x, kLargestInput);
    return clamp01((x * (a * x + b)) / (x * (c * x + d) + e));
}

float srgb_encode(float linear) {
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

uint8_t quantize8(float encoded) { return uint8_t(std::lround(clamp01(encoded) * 255.0f)); }

namespace {

// Where quantize8(srgb_encode(x)) steps up to 1, 2, ..., 255: the smallest float with that code,
// found by bisection over the bit patterns of the floats in [0, 1] (for positive floats they order
// as the integers do). The code never decreases as x grows, so counting the thresholds at or below
// x gives it.
const std::array<float, 255>& srgb8_thresholds() {
    static const std::array<float, 255> thresholds = [] {
        auto code = [](uint32_t bits) {
            float x;
            std::memcpy(&x, &bits, sizeof x);
            return int(quantize8(srgb_encode(x)));
        };
        uint32_t one;
        const float one_f = 1.0f;
        std::memcpy(&one, &one_f, sizeof one);
        std::array<float, 255> t{};
        for (int k = 1; k <= 255; ++k) {
            uint32_t lo = 0, hi = one;  // code(lo) < k <= code(hi)
            while (hi - lo > 1) {
                const uint32_t mid = lo + (hi - lo) / 2;
                (code(mid) >= k ? hi : lo) = mid;
            }
            std::memcpy(&t[size_t(k - 1)], &hi, sizeof hi);
        }
        return t;
    }();
    return thresholds;
}

// The code at the start of each of 4096 equal buckets of [0, 1]. Neighbouring codes' steps are at
// least 1 / (255 * 12.92) = 3.0e-4 apart (the curve's linear foot is its steepest part), more than a
// bucket's 2.4e-4, so a bucket holds at most one step: the bucket's code, plus one past its step.
constexpr int kSrgb8Buckets = 4096;

const std::array<uint8_t, kSrgb8Buckets>& srgb8_bucket_codes() {
    static const std::array<uint8_t, kSrgb8Buckets> codes = [] {
        const std::array<float, 255>& t = srgb8_thresholds();
        std::array<uint8_t, kSrgb8Buckets> c{};
        for (int b = 0; b < kSrgb8Buckets; ++b)
            c[size_t(b)] = uint8_t(std::upper_bound(t.begin(), t.end(), float(b) / float(kSrgb8Buckets)) - t.begin());
        return c;
    }();
    return codes;
}

}  // namespace

uint8_t srgb8_code(float display) {
    const std::array<float, 255>& t = srgb8_thresholds();
    const std::array<uint8_t, kSrgb8Buckets>& codes = srgb8_bucket_codes();
    if (!(display > 0.0f)) return 0;
    if (display >= 1.0f) return 255;
    const int code = codes[size_t(display * float(kSrgb8Buckets))];  // exact: a power of two
    return uint8_t(code + (code < 255 && display >= t[size_t(code)]));
}

namespace {

// tone_map_pixel with the exposure as its factor, 2^stops, worked out once per image.
void tone_map_scaled(const float in[3], ToneMap tone_map, float scale, float out[3]) {
    float c[3];
    for (int i = 0; i < 3; ++i) {
        const float v = in[i] * scale;
        c[i] = v > 0.0f ? std::min(v, kLargestInput) : 0.0f;  // also 0 for 0 * infinite scale
    }
    switch (tone_map) {
        case ToneMap::Aces:
            for (int i = 0; i < 3; ++i) out[i] = aces_narkowicz(c[i]);
            return;
        case ToneMap::Reinhard: {
            // L_d / L = 1 / (1 + L); also right for L = 0 (black stays black)
            const float s = 1.0f / (1.0f + luminance(c[0], c[1], c[2]));
            for (int i = 0; i < 3; ++i) out[i] = clamp01(c[i] * s);
            return;
        }
        case ToneMap::Clamp:
            for (int i = 0; i < 3; ++i) out[i] = clamp01(c[i]);
            return;
    }
}

}  // namespace

void tone_map_pixel(const float in[3], ToneMap tone_map, float exposure_stops, float out[3]) {
    tone_map_scaled(in, tone_map, std::exp2(exposure_stops), out);
}

std::vector<uint8_t> to_srgb8(const ImageRgb& image, ToneMap tone_map, float exposure_stops) {
    if (!image.valid()) throw std::invalid_argument("to_srgb8: the image's sizes do not match its data");
    if (!std::isfinite(exposure_stops)) throw std::invalid_argument("to_srgb8: the exposure is not finite");
    std::vector<uint8_t> out(image.rgb.size());
    const float scale = std::exp2(exposure_stops);
    for (size_t p = 0; p < image.rgb.size(); p += 3) {
        const float* in = &image.rgb[p];
        if (!std::isfinite(in[0]) || !std::isfinite(in[1]) || !std::isfinite(in[2])) {
            out[p] = 255, out[p + 1] = 0, out[p + 2] = 255;  // magenta: a NaN or infinity is a bug to be seen
            continue;
        }
        float display[3];
        tone_map_scaled(in, tone_map, scale, display);
        for (int i = 0; i < 3; ++i) out[p + size_t(i)] = srgb8_code(display[i]);
    }
    return out;
}

}  // namespace lab::film
