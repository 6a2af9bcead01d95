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

// The words of --aov, in the order their layers are written.
const std::vector<std::string>& aov_words();

// Parses a comma-separated list of aov_words() ("" selects none). Throws lab::InputError("--aov",
// ...) naming an unknown word, and when AOVs are asked of an output that holds no layers (`output`
// not an EXR), before anything is rendered.
AovSelection parse_aov_selection(const std::string& text, const std::string& output);

// The selected AOVs as EXR channels, in the order of aov_words(): the first-hit ones from
// `first_hits` (needed when selection.first_hit()), the others from the film of
// `samples_per_pixel` complete passes.
std::vector<film::ImageChannel> aov_channels(const FirstHitAovs* first_hits, const FilmReadback& film, int samples_per_pixel, int width,
                                             int height, const AovSelection& selection);

}  // namespace lab::render
