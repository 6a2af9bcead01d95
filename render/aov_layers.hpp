// `--aov`: which AOVs a render writes, and their EXR layers, named layer.channel as Blender's
// multilayer EXR and Mitsuba's aov integrator name passes (docs/render.md, "AOVs"):
// - first-hit (Renderer::first_hit_aovs): albedo.R/G/B, normal.X/Y/Z, depth.Z, and the material
//   slot as Blender's material index pass, IndexMA.X;
// - from the film (render/film_resolve): variance.R/G/B, the variance of each pixel's mean, and
//   samples.X, the finite samples the mean is over (Blender's sample count pass has one channel X).
#pragma once

#include <string>
#include <vector>

#include "film/image_output.hpp"
#include "render/film_readback.hpp"
#include "render/renderer.hpp"

namespace lab::render {

struct AovSelection {
    bool albedo = false, normal = false, depth = false, slot = false;  // first-hit
    bool variance = false, samples = false;                            // from the film
    bool first_hit() const { return albedo || normal || depth || slot; }
    bool any() const { return first_hit() || variance || samples; }
};

// Parses a comma-separated list of albedo, normal, depth, slot, variance, samples ("" selects
// none). Throws lab::InputError(option, ...) naming an unknown word, and when AOVs are asked of an
// output that holds no layers (`output` not an EXR), before anything is rendered.
AovSelection parse_aov_selection(const std::string& text, const std::string& output, const std::string& option = "--aov");

// The selected AOVs as EXR channels, in the order albedo, normal, depth, slot, variance, samples: the first-hit ones from
// `first_hits` (needed when selection.first_hit()), the others from the film of
// `samples_per_pixel` complete passes.
std::vector<film::ImageChannel> aov_channels(const FirstHitAovs* first_hits, const FilmReadback& film, int samples_per_pixel, int width,
                                             int height, const AovSelection& selection);

// Its two parts, for callers that hold the film's statistics already (the viewer's export): the
// selected first-hit layers, and the selected variance and samples layers from the variance of
// each pixel's mean and its finite sample count.
std::vector<film::ImageChannel> first_hit_channels(const FirstHitAovs& first_hits, const AovSelection& selection);
std::vector<film::ImageChannel> film_statistics_channels(const film::ImageRgb& variance, const std::vector<float>& samples,
                                                         const AovSelection& selection);

// The image's alpha, channel "A" (premultiplied, as the RGB is: over a plate P a compositor shows
// RGB + (1 - A) P): a pixel's covered share counts opaque, the rest as the backdrop's opacity, so
// A = coverage + (1 - coverage) opacity (docs/environments.md, "Background").
film::ImageChannel background_alpha_channel(const FirstHitAovs& aovs, float background_opacity);

}  // namespace lab::render
