// Tone curves, the sRGB transfer function and exposure, at values worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "common/input_error.hpp"
#include "film/tone_map.hpp"

using lab::film::ToneMap;

namespace {

std::array<float, 3> mapped(float r, float g, float b, ToneMap t, float stops) {
    const float in[3] = {r, g, b};
    std::array<float, 3> out{};
    lab::film::tone_map_pixel(in, t, stops, out.data());
    return out;
}

}  // namespace

TEST_CASE("tone map names parse, and an unknown one is one line naming the option", "[film]") {
    CHECK(lab::film::parse_tone_map("aces") == ToneMap::Aces);
    CHECK(lab::film::parse_tone_map("reinhard") == ToneMap::Reinhard);
    CHECK(lab::film::parse_tone_map("clamp") == ToneMap::Clamp);
    CHECK(std::string(lab::film::tone_map_name(ToneMap::Reinhard)) == "reinhard");
    try {
        lab::film::parse_tone_map("filmic");
        FAIL("no error for an unknown tone map");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "--tonemap: unknown tone map \"filmic\" (aces, reinhard, clamp)");
    }
}

TEST_CASE("the sRGB transfer function: IEC 61966-2-1 at known points", "[film]") {
    CHECK(lab::film::srgb_encode(0.0f) == 0.0f);
    CHECK(lab::film::srgb_encode(1.0f) == Approx(1.0f).margin(1e-6));
    CHECK(lab::film::srgb_encode(0.5f) == Approx(0.735357).margin(1e-6));
    // the two pieces meet: linear 0.0031308 <-> encoded 0.04045, from both sides
    CHECK(lab::film::srgb_encode(0.0031308f) == Approx(0.04045).margin(1e-6));
    CHECK(lab::film::srgb_encode(std::nextafter(0.0031308f, 1.0f)) == Approx(0.04045).margin(1e-6));
    CHECK(lab::film::srgb_encode(0.001f) == Approx(0.01292).margin(1e-8));  // the linear piece, 12.92 x
    CHECK(lab::film::srgb_decode(0.04045f) == Approx(0.0031308).margin(1e-8));
    CHECK(lab::film::srgb_decode(0.735357f) == Approx(0.5).margin(1e-6));
    for (float x : {0.0f, 0.002f, 0.01f, 0.2f, 0.5f, 0.9f, 1.0f}) CHECK(lab::film::srgb_decode(lab::film::srgb_encode(x)) == Approx(x).margin(1e-6));
    // 8 bits, rounded to nearest: 0.735357 * 255 = 187.516
    CHECK(lab::film::quantize8(0.0f) == 0);
    CHECK(lab::film::quantize8(1.0f) == 255);
    CHECK(lab::film::quantize8(lab::film::srgb_encode(0.5f)) == 188);
    CHECK(lab::film::quantize8(lab::film::srgb_encode(0.2f)) == 124);   // 123.555
    CHECK(lab::film::quantize8(lab::film::srgb_encode(0.001f)) == 3);   // 3.295
    CHECK(lab::film::quantize8(-0.5f) == 0);
    CHECK(lab::film::quantize8(1.5f) == 255);
}

TEST_CASE("ACES: the Narkowicz 2015 fit at known values, clamped to [0, 1]", "[film]") {
    CHECK(lab::film::aces_narkowicz(0.0f) == 0.0f);
    CHECK(lab::film::aces_narkowicz(1.0f) == Approx(2.54 / 3.16).epsilon(1e-6));  // 0.803797
    CHECK(lab::film::aces_narkowicz(0.5f) == Approx(0.616307).epsilon(1e-5));
    CHECK(lab::film::aces_narkowicz(0.18f) == Approx(0.266899).epsilon(1e-5));
    CHECK(lab::film::aces_narkowicz(10.0f) == 1.0f);  // the fit passes 1 at x ~ 7.24
    CHECK(lab::film::aces_narkowicz(1e30f) == 1.0f);
    auto a = mapped(0.18f, 1.0f, 0.0f, ToneMap::Aces, 0.0f);
    CHECK(a[0] == Approx(0.266899).epsilon(1e-5));
    CHECK(a[1] == Approx(0.803797).epsilon(1e-5));
    CHECK(a[2] == 0.0f);
}

TEST_CASE("Reinhard: L / (1 + L) on the luminance, as a scale of the colour", "[film]") {
    auto grey = mapped(1.0f, 1.0f, 1.0f, ToneMap::Reinhard, 0.0f);
    for (float c : grey) CHECK(c == Approx(0.5f).epsilon(1e-6));
    // L = 0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 0.125 = 0.294125; scale 1 / 1.294125
    auto colour = mapped(0.5f, 0.25f, 0.125f, ToneMap::Reinhard, 0.0f);
    CHECK(colour[0] == Approx(0.386361).epsilon(1e-5));
    CHECK(colour[1] == Approx(0.193181).epsilon(1e-5));
    CHECK(colour[2] == Approx(0.096590).epsilon(1e-5));
    CHECK(colour[0] / colour[1] == Approx(2.0f).epsilon(1e-6));  // hue kept
    // a saturated red's channel passes 1 after the scale: clamped
    auto red = mapped(4.0f, 0.0f, 0.0f, ToneMap::Reinhard, 0.0f);
    CHECK(red[0] == 1.0f);
    CHECK(red[1] == 0.0f);
    auto black = mapped(0.0f, 0.0f, 0.0f, ToneMap::Reinhard, 0.0f);
    CHECK(black[0] == 0.0f);
}

TEST_CASE("exposure: +1 stop doubles, -1 halves, before the curve - negatives are black", "[film]") {
    auto clamp_up = mapped(0.2f, 0.1f, 0.3f, ToneMap::Clamp, 1.0f);
    CHECK(clamp_up[0] == 0.4f);
    CHECK(clamp_up[1] == 0.2f);
    CHECK(clamp_up[2] == 0.6f);
    auto clamp_down = mapped(0.2f, 0.1f, 3.0f, ToneMap::Clamp, -1.0f);
    CHECK(clamp_down[0] == 0.1f);
    CHECK(clamp_down[2] == 1.0f);
    CHECK(mapped(0.18f, 0.18f, 0.18f, ToneMap::Aces, 1.0f)[0] == Approx(0.503644).epsilon(1e-5));  // ACES(0.36)
    CHECK(mapped(0.5f, 0.5f, 0.5f, ToneMap::Reinhard, 1.0f)[0] == Approx(0.5f).epsilon(1e-6));    // L = 1
    CHECK(mapped(-1.0f, 0.5f, 2.0f, ToneMap::Clamp, 0.0f)[0] == 0.0f);
    // a huge exposure does not turn black into NaN or a bright pixel into NaN
    auto huge = mapped(0.0f, 1.0f, 1e30f, ToneMap::Reinhard, 200.0f);
    CHECK(huge[0] == 0.0f);
    CHECK(std::isfinite(huge[1]));
    CHECK(huge[2] == 1.0f);
}

TEST_CASE("to_srgb8: tone map then sRGB then 8 bits - non-finite pixels are magenta", "[film]") {
    lab::film::ImageRgb image(3, 2);
    image.set(0, 0, 0.0f, 0.5f, 1.0f);
    image.set(1, 0, std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f);
    image.set(2, 0, 0.5f, std::numeric_limits<float>::infinity(), 0.5f);
    image.set(0, 1, 0.25f, 0.25f, 0.25f);
    image.set(1, 1, 100.0f, 0.2f, -3.0f);
    image.set(2, 1, 0.0f, 0.0f, -std::numeric_limits<float>::infinity());
    std::vector<uint8_t> px = lab::film::to_srgb8(image, ToneMap::Clamp, 0.0f);
    REQUIRE(px.size() == 18u);
    // 0.5 -> 187.516, 0.25 -> 136.96, 0.2 -> 123.555 (times 255)
    const std::vector<uint8_t> expected = {0, 188, 255, 255, 0, 255, 255, 0, 255, 137, 137, 137, 255, 124, 0, 255, 0, 255};
    CHECK(px == expected);
    // +1 stop: 0.25 -> 0.5 -> 188, the same bytes as 0.5 at 0 stops
    std::vector<uint8_t> brighter = lab::film::to_srgb8(image, ToneMap::Clamp, 1.0f);
    CHECK(int(brighter[9]) == 188);
    CHECK_THROWS_AS(lab::film::to_srgb8(image, ToneMap::Aces, std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
}

TEST_CASE("srgb8_code gives quantize8(srgb_encode(x)) for every float it was checked on", "[film][tone_map]") {
    // Every 61st float of [0, 1], and the floats within 3 ulps of every code's step.
    auto check = [](float x) {
        const int direct = int(lab::film::quantize8(lab::film::srgb_encode(x)));
        if (int(lab::film::srgb8_code(x)) != direct) {
            INFO("x = " << x);
            CHECK(int(lab::film::srgb8_code(x)) == direct);
            return false;
        }
        return true;
    };
    const float one = 1.0f;
    uint32_t top;
    std::memcpy(&top, &one, sizeof top);
    size_t checked = 0, wrong = 0;
    for (uint32_t bits = 0; bits <= top; bits += 61) {
        float x;
        std::memcpy(&x, &bits, sizeof x);
        wrong += !check(x);
        ++checked;
    }
    for (int code = 1; code <= 255; ++code) {
        // the step itself, from the closed form: encoded (code - 0.5) / 255, decoded
        const float step = lab::film::srgb_decode((float(code) - 0.5f) / 255.0f);
        uint32_t bits;
        std::memcpy(&bits, &step, sizeof bits);
        for (uint32_t b = bits - 3; b <= bits + 3; ++b) {
            float x;
            std::memcpy(&x, &b, sizeof x);
            wrong += !check(x);
            ++checked;
        }
    }
    CHECK(wrong == 0);
    CHECK(checked > 17000000);
    CHECK(lab::film::srgb8_code(-1.0f) == 0);
    CHECK(lab::film::srgb8_code(2.0f) == 255);
}
