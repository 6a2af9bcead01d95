#include "render/aov_layers.hpp"

#include <sstream>
#include <stdexcept>

#include "common/input_error.hpp"
#include "render/film_resolve.hpp"
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

AovSelection parse_aov_selection(const std::string& text, const std::string& output, const std::string& option) {
    AovSelection selection;
    std::stringstream words(text);
    for (std::string word; std::getline(words, word, ',');) {
        if (word == "albedo") selection.albedo = true;
        else if (word == "normal") selection.normal = true;
        else if (word == "depth") selection.depth = true;
        else if (word == "slot") selection.slot = true;
        else if (word == "variance") selection.variance = true;
        else if (word == "samples") selection.samples = true;
        else throw InputError(option, "", "unknown AOV \"" + word + "\" (expected a comma-separated list of albedo, normal, depth, slot, variance, samples)");
    }
    if (selection.any() && !is_exr_path(output))
        throw InputError(option, "", "AOVs are EXR layers, and " + output + " is not an .exr: write an .exr (a PNG is written beside it)");
    return selection;
}

std::vector<film::ImageChannel> first_hit_channels(const FirstHitAovs& first_hits, const AovSelection& selection) {
    std::vector<film::ImageChannel> channels;
    if (selection.albedo) add_channels(first_hits.albedo, "albedo", "RGB", &channels);
    if (selection.normal) add_channels(first_hits.normal, "normal", "XYZ", &channels);
    if (selection.depth) channels.push_back({"depth.Z", first_hits.depth});
    if (selection.slot) channels.push_back({"IndexMA.X", std::vector<float>(first_hits.slot.begin(), first_hits.slot.end())});
    return channels;
}

std::vector<film::ImageChannel> film_statistics_channels(const film::ImageRgb& variance, const std::vector<float>& samples,
                                                         const AovSelection& selection) {
    std::vector<film::ImageChannel> channels;
    if (selection.variance) add_channels(variance, "variance", "RGB", &channels);
    if (selection.samples) channels.push_back({"samples.X", samples});
    return channels;
}

std::vector<film::ImageChannel> aov_channels(const FirstHitAovs* first_hits, const FilmReadback& film, int samples_per_pixel, int width,
                                             int height, const AovSelection& selection) {
    if (selection.first_hit() && !first_hits) throw std::invalid_argument("aov_channels: first-hit AOVs selected but none given");
    std::vector<film::ImageChannel> channels = selection.first_hit() ? first_hit_channels(*first_hits, selection) : std::vector<film::ImageChannel>();
    const bool statistics = selection.variance || selection.samples;
    const std::vector<film::ImageChannel> more =
        statistics ? film_statistics_channels(resolve_variance(film, samples_per_pixel, width, height),
                                              finite_sample_counts(film, samples_per_pixel, width, height), selection)
                   : std::vector<film::ImageChannel>();
    channels.insert(channels.end(), more.begin(), more.end());
    return channels;
}

film::ImageChannel background_alpha_channel(const FirstHitAovs& aovs, float background_opacity) {
    film::ImageChannel alpha{"A", aovs.coverage};
    for (float& a : alpha.values) a += (1.0f - a) * background_opacity;
    return alpha;
}

}  // namespace lab::render
