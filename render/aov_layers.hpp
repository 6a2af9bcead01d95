// `--aov`: which first-hit AOVs a render writes (Renderer::first_hit_aovs), and their EXR layers,
// named layer.channel as Blender's multilayer EXR and Mitsuba's aov integrator name passes:
// albedo.R/G/B, normal.X/Y/Z, depth.Z (docs/render.md, "AOVs").
#pragma once

#include <string>
#include <vector>

#include "film/image_output.hpp"
#include "render/renderer.hpp"

namespace lab::render {

struct AovSelection {
    bool albedo = false, normal = false, depth = false;
    bool any() const { return albedo || normal || depth; }
};

// Parses a comma-separated list of albedo, normal, depth ("" selects none). Throws
// lab::InputError("--aov", ...) naming an unknown word, and when AOVs are asked of an output
// that holds no layers (`output` not an EXR), before anything is rendered.
AovSelection parse_aov_selection(const std::string& text, const std::string& output);

// The selected AOVs as EXR channels, in the order albedo, normal, depth.
std::vector<film::ImageChannel> aov_channels(const FirstHitAovs& aovs, const AovSelection& selection);

// The image's alpha, channel "A" (premultiplied, as the RGB is: over a plate P a compositor shows
// RGB + (1 - A) P): a pixel's covered share counts opaque, the rest as the backdrop's opacity, so
// A = coverage + (1 - coverage) opacity (docs/environments.md, "Background").
film::ImageChannel background_alpha_channel(const FirstHitAovs& aovs, float background_opacity);

}  // namespace lab::render
