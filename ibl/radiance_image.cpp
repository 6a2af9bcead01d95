#include "ibl/radiance_image.hpp"

#include <filesystem>
#include <memory>

#include "common/file_extension.hpp"
#include "common/image_claim.hpp"
#include "common/image_codec.hpp"
#include "common/image_open.hpp"
#include "common/input_error.hpp"

namespace lab::ibl {

const RadianceFormat kOpenExr{".exr", "openexr", "OpenEXR"};
const RadianceFormat kRadianceHdr{".hdr", "hdr", "Radiance HDR"};
const RadianceFormat kPng{".png", "png", "PNG"};
const std::vector<RadianceFormat> kVideos{{".mp4", "FFmpeg movie", "MP4"}, {".mov", "FFmpeg movie", "QuickTime"}, {".mkv", "FFmpeg movie", "Matroska"},
                                          {".avi", "FFmpeg movie", "AVI"}, {".webm", "FFmpeg movie", "WebM"}};

namespace {

// "a", "a or b", "a, b or c" of one field of the formats.
std::string alternatives(const std::vector<RadianceFormat>& formats, std::string RadianceFormat::*field) {
    std::string text;
    for (size_t k = 0; k < formats.size(); ++k) {
        if (k > 0) text += k + 1 == formats.size() ? " or " : ", ";
        text += formats[k].*field;
    }
    return text;
}

}  // namespace

RadianceImage read_radiance_image(const std::string& path, const std::vector<RadianceFormat>& formats,
                                  const std::function<void(int width, int height)>& check_size, int subimage) {
    const std::string ext = lowercase_extension(path);
    bool known = false;
    for (const RadianceFormat& f : formats) known = known || f.extension == ext;
    std::error_code ec;
    if (!known && std::filesystem::is_regular_file(path, ec))
        throw InputError(path, "", "unsupported image format \"" + ext + "\" (expected " + alternatives(formats, &RadianceFormat::extension) + ")");

    const std::string names = alternatives(formats, &RadianceFormat::name);
    std::unique_ptr<codec::ImageFile> input = codec::open_flat_image(path, "an " + names + " image", "");
    const codec::Header& header = input->header();
    bool accepted = false;
    for (const RadianceFormat& f : formats) accepted = accepted || f.format == header.format;
    if (!accepted) throw InputError(path, "", "holds a " + header.format + " image, not " + names);
    check_size(header.width, header.height);
    const int channels = header.channels;
    if (channels != 1 && channels < 3)
        throw InputError(path, "channels", std::to_string(channels) + " (expected 1 for grey, or 3 or more with R, G, B first)");

    const int used = channels == 1 ? 1 : 3;
    // what is read, and for grey the RGB image made from it besides, before a pixel is allocated
    codec::check_image_file_claim(path, header, used == 1 ? 4 : 3);
    RadianceImage image;
    image.width = header.width;
    image.height = header.height;
    image.format = header.format;
    image.pixels.resize(size_t(header.width) * size_t(header.height) * size_t(used));
    std::string error;
    if (!input->read_subimage(subimage, used, image.pixels.data(), &error)) throw InputError(path, "pixels", "cannot be read (corrupt or truncated file)");
    image.channel_names.assign(header.channel_names.begin(), header.channel_names.begin() + used);
    return image;
}

}  // namespace lab::ibl
