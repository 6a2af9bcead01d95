#include "render/aov_layers.hpp"

#include <sstream>

#include "common/input_error.hpp"
#include "render/progressive.hpp"

namespace lab::render {

namespace {

// An RGB image's three channels under `layer`, with the channel letters `names`.
void add_channels(const film::ImageRgb& image, const std::string& layer, const char* names, std::vector<film::ImageChannel>* out) {
    for (int c = 0; c < 3; ++c) {
        film::ImageChannel channel{layer + "." + names[c], std::vector<float>(image.pixel_count())};
        for (size_t p = 0; p < image.pixel_count(); ++p) channel.values[p] = image.rgb[3 * p + size_t(c)];
        out->push_back(std::move(channel));
    }
}

}  // namespace

AovSelection parse_aov_selection(const std::string& text, const std::string& output) {
    AovSelection selection;
    std::stringstream words(text);
    for (std::string word; std::getline(words, word, ',');) {
        if (word == "albedo") selection.albedo = true;
        else if (word == "normal") selection.normal = true;
        else if (word == "depth") selection.depth = true;
        else throw InputError("--aov", "", "unknown AOV \"" + word + "\" (expected a comma-separated list of albedo, normal, depth)");
    }
    if (selection.any() && !is_exr_path(output))
        throw InputError("--aov", "", "AOVs are EXR layers, and " + output + " is not an .exr: write an .exr (a PNG is written beside it)");
    return selection;
}

std::vector<film::ImageChannel> aov_channels(const FirstHitAovs& aovs, const AovSelection& selection) {
    std::vector<film::ImageChannel> channels;
    if (selection.albedo) add_channels(aovs.albedo, "albedo", "RGB", &channels);
    if (selection.normal) add_channels(aovs.normal, "normal", "XYZ", &channels);
    if (selection.depth) channels.push_back({"depth.Z", aovs.depth});
    return channels;
}

film::ImageChannel background_alpha_channel(const FirstHitAovs& aovs, float background_opacity) {
    film::ImageChannel alpha{"A", aovs.coverage};
    for (float& a : alpha.values) a += (1.0f - a) * background_opacity;
    return alpha;
}

}  // namespace lab::render
