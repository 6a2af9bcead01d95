// The viewer's view menu: what each view shows of a render, as the 8-bit sRGB bytes the texture
// takes (film::to_srgb8's layout). Pure functions of the published frame, without ImGui, so that
// the tests check each mapping (tests/test_viewer_view_modes.cpp); docs/viewer.md, "Views".
//  - image: the render, tone-mapped (film::to_srgb8);
//  - albedo, normal, depth, slot: the first-hit AOVs (render::FirstHitAovs); samples, variance:
//    the film's (render::finite_sample_counts, render::resolve_variance);
//  - false colour: the luminance after exposure in stops from middle grey (0.18), one colour a
//    stop, with its legend (false_colour_legend);
//  - relative error: pixels whose standard error over their mean luminance is above a threshold,
//    red over the image in grey: where to wait longer;
//  - gamut: non-finite pixels magenta, a negative channel (outside the sRGB gamut) cyan, a channel
//    above 1 after exposure (beyond a display's range) red, the rest the image in grey.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "film/image.hpp"
#include "film/tone_map.hpp"
#include "render/renderer.hpp"

namespace lab::viewer {

enum class ViewMode { image, albedo, normal, depth, slot, samples, variance, false_colour, relative_error, gamut };

// Every mode with its name (the menu's entries and --view-mode's words), in menu order.
const std::vector<std::pair<ViewMode, std::string>>& view_modes();
const std::string& view_mode_name(ViewMode mode);
// A name of view_modes(); throws lab::InputError(option, "", ...) listing them otherwise.
ViewMode parse_view_mode(const std::string& text, const std::string& option);

// What a mode needs beyond the image.
bool needs_first_hits(ViewMode mode);        // albedo, normal, depth, slot
bool needs_film_statistics(ViewMode mode);   // samples, variance, relative error

// What the views are made from; the pointers a mode needs must be set (view_pixels says when not).
struct ViewInputs {
    const film::ImageRgb* image = nullptr;
    const render::FirstHitAovs* first_hits = nullptr;
    const film::ImageRgb* variance = nullptr;   // of each pixel's mean, per channel
    const std::vector<float>* samples = nullptr;  // finite samples per pixel
    film::ToneMap tone_map = film::ToneMap::Aces;
    float exposure_stops = 0.0f;
    float relative_error_threshold = 0.05f;     // the relative error view's
};

// The view's bytes (3 per pixel of the image), or none when an input it needs is missing or of
// another size than the image (the viewer shows the image until they come).
std::vector<uint8_t> view_pixels(ViewMode mode, const ViewInputs& in);

// The standard error of a pixel mean's luminance from its channels' variances: at most the sum of
// the channels' weighted standard errors (their samples are correlated, as one path carries all
// three), which this takes, so the error is never understated.
float luminance_standard_error(const float variance[3]);

// The false-colour view's bands: luminance in [lo_stops, hi_stops) stops from middle grey
// (lo -inf for the first, hi +inf for the last) shows as `rgb`.
struct LegendBand {
    float lo_stops, hi_stops;
    std::array<uint8_t, 3> rgb;
};
const std::vector<LegendBand>& false_colour_legend();
constexpr float kMiddleGrey = 0.18f;

// The colours the flagging views paint with.
constexpr std::array<uint8_t, 3> kFlagRed = {255, 0, 0}, kNonFiniteMagenta = {255, 0, 255}, kNegativeCyan = {0, 255, 255};

}  // namespace lab::viewer
