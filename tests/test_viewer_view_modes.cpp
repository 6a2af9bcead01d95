// The view menu's mappings (viewer/view_modes), pixel by pixel on small made-up inputs whose
// displayed codes follow from each view's definition (docs/viewer.md, "Views").
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>

#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "viewer/view_modes.hpp"

using lab::viewer::ViewInputs;
using lab::viewer::ViewMode;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();

std::array<uint8_t, 3> pixel(const std::vector<uint8_t>& bytes, size_t p) { return {bytes[3 * p], bytes[3 * p + 1], bytes[3 * p + 2]}; }

// A 4x1 image with first-hit AOVs and film statistics, each pixel's set by the test.
struct Frame {
    lab::film::ImageRgb image{4, 1}, variance{4, 1};
    lab::render::FirstHitAovs hits{lab::film::ImageRgb(4, 1), lab::film::ImageRgb(4, 1), std::vector<float>(4, 0.0f), std::vector<float>(4, 0.0f),
                                   std::vector<int>(4, -1)};
    std::vector<float> samples = std::vector<float>(4, 8.0f);
    ViewInputs inputs() const {
        ViewInputs in;
        in.image = &image;
        in.first_hits = &hits;
        in.variance = &variance;
        in.samples = &samples;
        return in;
    }
};

std::array<uint8_t, 3> grey(float display) {
    const uint8_t g = lab::film::quantize8(display);
    return {g, g, g};
}

}  // namespace

TEST_CASE("View modes: every name parses back to its mode; an unknown one names the option", "[viewer][view-modes]") {
    for (const auto& [mode, name] : lab::viewer::view_modes()) {
        CHECK(lab::viewer::parse_view_mode(name, "--view-mode") == mode);
        CHECK(lab::viewer::view_mode_name(mode) == name);
    }
    CHECK(lab::viewer::view_modes().size() == 10);
    CHECK_THROWS_WITH(lab::viewer::parse_view_mode("albedoo", "--view-mode"), Catch::Contains("--view-mode") && Catch::Contains("albedoo"));
}

TEST_CASE("View modes: the image is the tone-mapped render; a view whose inputs are missing or of another size gives none",
          "[viewer][view-modes]") {
    Frame f;
    f.image.set(0, 0, 0.3f, 0.2f, 0.1f);
    ViewInputs in = f.inputs();
    CHECK(lab::viewer::view_pixels(ViewMode::image, in) == lab::film::to_srgb8(f.image, lab::film::ToneMap::Aces, 0.0f));
    in.first_hits = nullptr;
    in.samples = nullptr;
    for (ViewMode mode : {ViewMode::albedo, ViewMode::normal, ViewMode::depth, ViewMode::slot, ViewMode::samples, ViewMode::variance,
                          ViewMode::relative_error})
        CHECK(lab::viewer::view_pixels(mode, in).empty());
    Frame other_size;
    other_size.hits.albedo = lab::film::ImageRgb(2, 2);
    CHECK(lab::viewer::view_pixels(ViewMode::albedo, other_size.inputs()).empty());  // as many pixels, another shape
    CHECK(lab::viewer::view_pixels(ViewMode::normal, other_size.inputs()).empty());  // the first-hit AOVs go together
    CHECK_FALSE(lab::viewer::view_pixels(ViewMode::variance, other_size.inputs()).empty());
}

TEST_CASE("View modes: albedo, normal, depth and slot show the first-hit AOVs", "[viewer][view-modes]") {
    Frame f;
    f.hits.albedo.set(0, 0, 0.6f, 0.04f, 0.03f);
    f.hits.normal.set(0, 0, 0.0f, 0.0f, 1.0f);
    f.hits.normal.set(1, 0, -1.0f, 0.0f, 0.0f);
    f.hits.depth = {2.0f, 3.0f, 4.0f, 0.0f};
    f.hits.slot = {0, 1, 8, -1};
    const ViewInputs in = f.inputs();
    const std::vector<uint8_t> albedo = lab::viewer::view_pixels(ViewMode::albedo, in);
    CHECK(pixel(albedo, 0) == std::array<uint8_t, 3>{lab::film::srgb8_code(0.6f), lab::film::srgb8_code(0.04f), lab::film::srgb8_code(0.03f)});
    const std::vector<uint8_t> normal = lab::viewer::view_pixels(ViewMode::normal, in);
    CHECK(pixel(normal, 0) == std::array<uint8_t, 3>{128, 128, 255});
    CHECK(pixel(normal, 1) == std::array<uint8_t, 3>{0, 128, 128});
    CHECK(pixel(normal, 2) == std::array<uint8_t, 3>{0, 0, 0});  // no surface
    const std::vector<uint8_t> depth = lab::viewer::view_pixels(ViewMode::depth, in);
    CHECK(pixel(depth, 0) == grey(1.0f));  // nearest
    CHECK(pixel(depth, 1) == grey(2.0f / 3.0f));
    CHECK(pixel(depth, 2) == grey(0.5f));  // twice as far
    CHECK(pixel(depth, 3) == grey(0.0f));  // no surface
    const std::vector<uint8_t> slot = lab::viewer::view_pixels(ViewMode::slot, in);
    CHECK(pixel(slot, 0) != pixel(slot, 1));
    CHECK(pixel(slot, 0) == pixel(slot, 2));  // eight colours, then again
    CHECK(pixel(slot, 3) == std::array<uint8_t, 3>{0, 0, 0});
}

TEST_CASE("View modes: samples over the largest count, the mean's standard error over its 99th percentile", "[viewer][view-modes]") {
    Frame f;
    f.samples = {8.0f, 4.0f, 8.0f, 0.0f};
    const std::vector<uint8_t> samples = lab::viewer::view_pixels(ViewMode::samples, f.inputs());
    CHECK(pixel(samples, 0) == grey(1.0f));
    CHECK(pixel(samples, 1) == grey(0.5f));
    CHECK(pixel(samples, 3) == grey(0.0f));
    f.variance.set(0, 0, 4.0f, 4.0f, 4.0f);     // standard error 2 (the luminance weights sum to 1)
    f.variance.set(1, 0, 1.0f, 1.0f, 1.0f);     // 1: the 99th percentile of 2, 1, 0.5
    f.variance.set(2, 0, 0.25f, 0.25f, 0.25f);  // 0.5
    f.variance.set(3, 0, kNaN, kNaN, kNaN);     // fewer than two samples
    std::vector<uint8_t> variance = lab::viewer::view_pixels(ViewMode::variance, f.inputs());
    CHECK(pixel(variance, 0) == grey(1.0f));  // above the percentile: white
    CHECK(pixel(variance, 1) == grey(1.0f));
    CHECK(pixel(variance, 2) == grey(std::sqrt(0.5f)));
    CHECK(pixel(variance, 3) == lab::viewer::kNonFiniteMagenta);
    f.variance.set(2, 0, 0.0f, 0.0f, 0.0f);
    variance = lab::viewer::view_pixels(ViewMode::variance, f.inputs());
    CHECK(pixel(variance, 2) == grey(0.0f));
    const float v[3] = {0.04f, 0.01f, 0.09f};
    CHECK(lab::viewer::luminance_standard_error(v) == Approx(0.2126 * 0.2 + 0.7152 * 0.1 + 0.0722 * 0.3).epsilon(1e-6));
}

TEST_CASE("View modes: false colour puts the luminance's stops from middle grey in the legend's bands", "[viewer][view-modes]") {
    const std::vector<lab::viewer::LegendBand>& bands = lab::viewer::false_colour_legend();
    auto band_of = [&](float stops) {
        for (const lab::viewer::LegendBand& b : bands)
            if (stops >= b.lo_stops && stops < b.hi_stops) return b.rgb;
        return std::array<uint8_t, 3>{1, 2, 3};
    };
    Frame f;
    const float g = lab::viewer::kMiddleGrey;
    f.image.set(0, 0, g, g, g);                                  // 0 stops
    f.image.set(1, 0, g * 5.66f, g * 5.66f, g * 5.66f);          // 2.5 stops
    f.image.set(2, 0, 0.0f, 0.0f, 0.0f);                         // black: the lowest band
    f.image.set(3, 0, kNaN, 0.0f, 0.0f);
    ViewInputs in = f.inputs();
    std::vector<uint8_t> bytes = lab::viewer::view_pixels(ViewMode::false_colour, in);
    CHECK(pixel(bytes, 0) == band_of(0.5f));
    CHECK(pixel(bytes, 1) == band_of(2.5f));
    CHECK(pixel(bytes, 1) != pixel(bytes, 0));
    CHECK(pixel(bytes, 2) == bands.front().rgb);
    CHECK(pixel(bytes, 3) == lab::viewer::kNonFiniteMagenta);
    in.exposure_stops = 1.0f;  // exposure moves every pixel one band up
    bytes = lab::viewer::view_pixels(ViewMode::false_colour, in);
    CHECK(pixel(bytes, 0) == band_of(1.5f));
    CHECK(pixel(bytes, 1) == band_of(3.5f));
    // the bands tile the line: one band for any stops
    for (float s = -8.0f; s <= 8.0f; s += 0.25f) CHECK(band_of(s) != std::array<uint8_t, 3>{1, 2, 3});
}

TEST_CASE("View modes: the relative-error view marks pixels whose standard error over their mean is above the threshold",
          "[viewer][view-modes]") {
    Frame f;
    for (int x = 0; x < 4; ++x) f.image.set(x, 0, 1.0f, 1.0f, 1.0f);
    f.variance.set(0, 0, 0.01f, 0.01f, 0.01f);  // relative error 0.1
    f.variance.set(1, 0, 1e-4f, 1e-4f, 1e-4f);  // 0.01
    f.variance.set(2, 0, kNaN, kNaN, kNaN);     // no estimate: uncertain
    f.image.set(3, 0, 0.0f, 0.0f, 0.0f);        // black without spread: certain
    ViewInputs in = f.inputs();
    in.relative_error_threshold = 0.05f;
    std::vector<uint8_t> bytes = lab::viewer::view_pixels(ViewMode::relative_error, in);
    CHECK(pixel(bytes, 0) == lab::viewer::kFlagRed);
    CHECK(pixel(bytes, 1) != lab::viewer::kFlagRed);
    CHECK(pixel(bytes, 2) == lab::viewer::kFlagRed);
    CHECK(pixel(bytes, 3) == grey(0.0f));
    in.relative_error_threshold = 0.2f;
    bytes = lab::viewer::view_pixels(ViewMode::relative_error, in);
    CHECK(pixel(bytes, 0) != lab::viewer::kFlagRed);
    // the samples' variance instead of the mean's (64 times larger at 64 spp) marks pixel 1 too
    f.variance.set(1, 0, 64e-4f, 64e-4f, 64e-4f);
    in.relative_error_threshold = 0.05f;
    CHECK(pixel(lab::viewer::view_pixels(ViewMode::relative_error, in), 1) == lab::viewer::kFlagRed);
}

TEST_CASE("View modes: the gamut view marks non-finite, negative and over-range pixels", "[viewer][view-modes]") {
    Frame f;
    f.image.set(0, 0, kNaN, 0.5f, 0.5f);
    f.image.set(1, 0, -0.01f, 0.5f, 0.5f);
    f.image.set(2, 0, 0.2f, 1.5f, 0.2f);
    f.image.set(3, 0, 0.3f, 0.3f, 0.3f);
    ViewInputs in = f.inputs();
    std::vector<uint8_t> bytes = lab::viewer::view_pixels(ViewMode::gamut, in);
    CHECK(pixel(bytes, 0) == lab::viewer::kNonFiniteMagenta);
    CHECK(pixel(bytes, 1) == lab::viewer::kNegativeCyan);
    CHECK(pixel(bytes, 2) == lab::viewer::kFlagRed);
    const uint8_t dimmed = lab::film::srgb8_code(0.5f * lab::film::aces_narkowicz(0.3f));
    CHECK(pixel(bytes, 3) == std::array<uint8_t, 3>{dimmed, dimmed, dimmed});
    in.exposure_stops = 2.0f;  // 0.3 * 4 = 1.2: beyond the display's range
    bytes = lab::viewer::view_pixels(ViewMode::gamut, in);
    CHECK(pixel(bytes, 3) == lab::viewer::kFlagRed);
}
