// An image file of radiance, read the one way the lab reads lighting from images (environments,
// ibl/environment.hpp, and the images rect and disk emitters show, render/emitter_images.hpp): the
// file checked against a list of formats, its header's claim against the file and the machine
// (common/image_claim.hpp) before a pixel is allocated, every failure one line naming the file.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace lab::ibl {

// One of the formats read_radiance_image may accept.
struct RadianceFormat {
    std::string extension;  // lowercase, with its dot: ".exr"
    std::string format;     // OpenImageIO's name: "openexr"
    std::string name;       // for messages: "OpenEXR"
};

extern const RadianceFormat kOpenExr, kRadianceHdr, kPng;
// The video files OpenImageIO's FFmpeg reader opens, each frame a subimage (ibl/frame_source.hpp).
extern const std::vector<RadianceFormat> kVideos;

struct RadianceImage {
    int width = 0, height = 0;
    std::string format;                      // OpenImageIO's name of the format read
    std::vector<float> pixels;               // width x height x channel_names.size(), rows from the top
    std::vector<std::string> channel_names;  // 1 (grey) or 3 (R, G, B)
};

// The first channel of a grey image, or the first three (R, G, B) of one with three or more, as
// stored (a PNG's values still sRGB-encoded, in [0, 1]). check_size(width, height) runs on the
// header's size before anything else is read (it throws lab::InputError naming `path` and "size").
// Throws lab::InputError naming the file for a missing or unreadable file, an extension or a format
// not in `formats`, a deep image, 2 channels, a claim the file or the memory cannot hold, and
// pixels that cannot be read. `subimage` is the one read: a video's frame (0 for any other file).
RadianceImage read_radiance_image(const std::string& path, const std::vector<RadianceFormat>& formats,
                                  const std::function<void(int width, int height)>& check_size, int subimage = 0);

}  // namespace lab::ibl
