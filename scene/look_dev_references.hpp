// Look-dev reference objects, as film look-dev shows them beside an asset so that a material can be
// told from its lighting: a chrome ball (the lighting's reflection), an 18 % grey ball (its
// irradiance on a known reflectance) and a ColorChecker chart (24 matte patches of published
// colours). They are placed in the camera's view, in its lower corners, at 0.7 of the way to the
// look-at point, sized to the view, so they sit in front of any scene's subject. Each is a plain
// primitive under rigid transforms, so it is intersected exactly (scene/geometry_paths.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace lab::scene {

// With them, as the look-dev staging they share a switch with, the shadow catcher that takes the
// ground's place (scene/shadow_catcher.hpp; `--shadow-catcher`, the word "catcher").
struct LookDevReferences {
    bool chrome_ball = false, grey_ball = false, color_chart = false;
    bool shadow_catcher = false;
    bool any() const { return chrome_ball || grey_ball || color_chart || shadow_catcher; }
};
// "none", "all" (the three references), or a comma list of chrome, grey, chart, catcher; throws
// lab::InputError(option, ...) otherwise.
LookDevReferences parse_look_dev_references(const std::string& text, const std::string& option);
// The words parse_look_dev_references reads back as `references`: "none", or e.g. "chrome,chart".
std::string look_dev_references_text(const LookDevReferences& references);

// One ColorChecker Classic patch: its name and its 8-bit sRGB value as published by D. Pascale,
// "RGB coordinates of the Macbeth ColorChecker", The BabelColor Company, 2006 (the average of
// measured charts, converted to sRGB under D65). The material's albedo is the value decoded to
// linear sRGB; the patches are matte (Lambert).
struct ColorCheckerPatch {
    const char* name;
    std::array<uint8_t, 3> srgb8;
};
// In the chart's reading order: row by row from the top left (dark skin) to the bottom right (black).
extern const std::array<ColorCheckerPatch, 24> kColorCheckerPatches;

// The reference materials and their objects' names and slots: "reference_chrome", "reference_grey",
// "reference_chart_<patch>" (patch names in lower case with underscores).
constexpr float kGreyBallAlbedo = 0.18f;
// Chromium's reflectance at normal incidence, linear sRGB (Hoffman, "Physics and Math of Shading",
// SIGGRAPH 2015 course notes, table of metals).
constexpr float kChromeF0[3] = {0.549f, 0.556f, 0.554f};

// The scene with the references added: their material slots after all of the scene's (whose
// indices do not change), their objects after the scene's; the shadow catcher's first
// (with_shadow_catcher). `aspect` (width / height of the image) places them in the view's corners.
Scene with_look_dev_references(const Scene& scene, const LookDevReferences& which, float aspect);

}  // namespace lab::scene
