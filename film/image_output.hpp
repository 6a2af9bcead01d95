// Image files: linear float EXR (the data) and tone-mapped 8-bit sRGB PNG (for looking at), both
// with metadata, both written atomically; and reading them back (references, tests).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "film/image.hpp"
#include "film/image_metadata.hpp"
#include "film/tone_map.hpp"

namespace lab::film {

// Called before rendering, so a bad path fails in a second, not after the render. Throws
// lab::InputError(path, "", ...) when the extension is not .exr or .png (any case), the folder
// does not exist or cannot be written, the path is a folder, or an existing file there is read-only;
// std::runtime_error when the image codec (common/image_codec.hpp) cannot be loaded.
void check_output_path(const std::string& path);

// Writes PATH as .exr or .png by its extension (as check_output_path accepts); the PNG is
// tone-mapped, the EXR ignores tone_map and exposure_stops (but they belong in the metadata).
void write_image(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata);

// A channel besides R, G, B in an EXR: one float per pixel, named as OpenEXR names layers
// ("film.sum.R"). A render keeps the film it was resolved from this way (render/film_file.hpp).
struct ImageChannel {
    std::string name;
    std::vector<float> values;
};

// Linear float32 RGB OpenEXR (zip compression), every value as it is, NaN and infinity included,
// with the `extra` channels after R, G, B (each one float per pixel).
void write_exr(const std::string& path, const ImageRgb& image, const ImageMetadata& metadata, const std::vector<ImageChannel>& extra = {});

// 8-bit sRGB PNG: to_srgb8(image, tone_map, exposure_stops), non-finite pixels magenta.
void write_png(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata);

// The same file from pixels already 8-bit sRGB: width x height x 3 bytes, rows from the top (the
// viewer's screenshot).
void write_srgb8_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, const ImageMetadata& metadata);

// Both writers encode the whole file in memory, write it to a new temporary file in the same
// folder and rename that over PATH: a write that fails (disk full, folder gone, a folder in the
// way) throws lab::InputError(path, "", "cannot write: ...") and leaves an existing PATH as it was
// and no partial file behind. An image whose sizes do not match its data is std::invalid_argument.

// Reads an OpenEXR or PNG file (the format is found from the content): the R, G, B channels (a
// one-channel image is grey). EXR values come back as stored; PNG values are decoded from sRGB to
// linear with srgb_decode (the tone curve is not undone). metadata, when given, receives the
// "dtoadq:*" attributes and "Software". Errors throw lab::InputError naming the file.
ImageRgb read_image(const std::string& path, ImageMetadata* metadata = nullptr);

// The named channels of an OpenEXR file, bit for bit, in the order asked, and its size. Throws
// lab::InputError(path, name, ...) for the first channel the file lacks, and as read_image does.
std::vector<ImageChannel> read_exr_channels(const std::string& path, const std::vector<std::string>& names, int* width, int* height);

}  // namespace lab::film
