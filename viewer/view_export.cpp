#include "viewer/view_export.hpp"

#include "common/input_error.hpp"
#include "render/progressive.hpp"

namespace lab::viewer {

bool frame_has_layers(const RenderFrame& frame, const render::AovSelection& selection) {
    if (!frame.image.valid()) return false;
    const bool statistics = selection.variance || selection.samples;
    if (selection.first_hit() && !(frame.first_hits && frame.first_hits->albedo.width == frame.image.width &&
                                   frame.first_hits->albedo.height == frame.image.height))
        return false;
    return !statistics || (frame.variance.width == frame.image.width && frame.variance.height == frame.image.height &&
                           frame.samples.size() == frame.image.pixel_count());
}

void save_frame_exr(const std::string& path, const RenderFrame& frame, const render::AovSelection& selection, film::ToneMap tone_map,
                    float exposure_stops) {
    if (!frame_has_layers(frame, selection))
        throw InputError(path, "", "the frame shown has no full-size image with the chosen layers yet (they come after the first full pass)");
    std::vector<film::ImageChannel> layers = selection.first_hit() ? render::first_hit_channels(*frame.first_hits, selection)
                                                                   : std::vector<film::ImageChannel>();
    const std::vector<film::ImageChannel> statistics = render::film_statistics_channels(frame.variance, frame.samples, selection);
    layers.insert(layers.end(), statistics.begin(), statistics.end());
    film::ImageMetadata metadata;
    metadata.set("spp", frame.samples_per_pixel);
    metadata.set("first_hit_samples", kViewFirstHitSamples);
    metadata.set("tonemap", film::tone_map_name(tone_map));
    metadata.set("exposure", exposure_stops);
    render::write_render_images(path, frame.image, tone_map, exposure_stops, metadata, nullptr, layers);
}

}  // namespace lab::viewer
