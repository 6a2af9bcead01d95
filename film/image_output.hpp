// Image files: linear float EXR (the data) and tone-mapped 8-bit sRGB PNG (for looking at), both
// with metadata, both written atomically; and reading them back (references, tests).
#pragma once

#include <string>

#include "film/image.hpp"
#include "film/image_metadata.hpp"
#include "film/tone_map.hpp"

namespace lab::film {

// Called before rendering, so a bad path fails in a second, not after the render. Throws
// lab::InputError(path, "", ...) when the extension is not .exr or .png (any case), the folder
// does not exist or cannot be written, the path is a folder, or an existing file there is read-only.
void check_output_path(const std::string& path);

// Writes PATH as .exr or .png by its extension (as check_output_path accepts); the PNG is
// tone-mapped, the EXR ignores tone_map and exposure_stops (but they belong in the metadata).
void write_image(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata);

// Linear float32 RGB OpenEXR (zip compression), every value as it is, NaN and infinity included.
void write_exr(const std::string& path, const ImageRgb& image, const ImageMetadata& metadata);

// 8-bit sRGB PNG: to_srgb8(image, tone_map, exposure_stops), non-finite pixels magenta.
void write_png(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata);

// Both writers encode the whole file in memory, write it to a new temporary file in the same
// folder and rename that over PATH: a write that fails (disk full, folder gone, a folder in the
// way) throws lab::InputError(path, "", "cannot write: ...") and leaves an existing PATH as it was
// and no partial file behind. An image whose sizes do not match its data is std::invalid_argument.

// Reads an OpenEXR or PNG file (the format is found from the content): the R, G, B channels (a
// one-channel image is grey). EXR values come back as stored; PNG values are decoded from sRGB to
// linear with srgb_decode (the tone curve is not undone). metadata, when given, receives the
// "dtoadq:*" attributes and "Software". Errors throw lab::InputError naming the file.
ImageRgb read_image(const std::string& path, ImageMetadata* metadata = nullptr);

}  // namespace lab::film
