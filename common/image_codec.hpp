// The lab's one door to OpenImageIO: image files opened, read and encoded by a module of their own
// (common/image_codec_oiio.cpp, built as libdtoadq_image_codec.so), which the first image read or
// written loads (common/image_codec_loader.cpp). OpenImageIO brings some 260 shared libraries, whose
// loading costs a process about 0.25 s of CPU before main(); a command that reads and writes no
// image (a lobe plot, an evaluation, every input error found before a render) starts without them.
// Plain data across the border, so the module needs no lab library. (The sanitized build links it
// in instead: common/CMakeLists.txt says why.)
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace lab::codec {

// An image file's attribute (OpenImageIO's name): an int, a float or a string.
struct Attribute {
    enum class Kind { integer, real, text };
    std::string name;
    Kind kind = Kind::text;
    int integer = 0;
    float real = 0.0f;
    std::string text;
};

struct Header {
    std::string format;  // OpenImageIO's name of the file's format: "openexr", "png", "hdr", ...
    int width = 0, height = 0, channels = 0;
    bool deep = false;
    bool floating = false;  // the file stores floats or halves (OpenEXR, Radiance, float TIFF), not integers
    std::vector<std::string> channel_names;
    std::vector<Attribute> attributes;  // every attribute besides the above
};

// An open image file.
class ImageFile {
public:
    virtual ~ImageFile() = default;
    virtual const Header& header() const = 0;
    // The first `channels` channels of every pixel as floats, interleaved (width * height *
    // channels). False, with OpenImageIO's message in *error, when the pixels cannot be read.
    virtual bool read(int channels, float* pixels, std::string* error) = 0;
    // The same for subimage `index`: a video's frame (OpenImageIO's FFmpeg reader gives each frame
    // as a subimage of the header's size, and their count as the attribute "oiio:subimages").
    virtual bool read_subimage(int index, int channels, float* pixels, std::string* error) = 0;
};

// What to encode: `channels` values per pixel, 8-bit (`bytes`) or float, interleaved.
struct Encoding {
    std::string format;  // "openexr", "png", ...; empty: from the path's extension
    int width = 0, height = 0, channels = 0;
    bool bytes = false;
    const void* pixels = nullptr;
    std::vector<std::string> channel_names;  // empty: OpenImageIO's (R, G, B, A, channel4, ...)
    std::vector<Attribute> attributes;
};

class ImageCodec {
public:
    virtual ~ImageCodec() = default;
    // nullptr, with OpenImageIO's message in *error, when no reader opens the file.
    virtual std::unique_ptr<ImageFile> open(const std::string& path, std::string* error) const = 0;
    // The encoded file (`path` names it for the format and the messages; nothing is written). False,
    // with OpenImageIO's message in *error, when it cannot be encoded.
    virtual bool encode(const std::string& path, const Encoding& image, std::vector<unsigned char>* file, std::string* error) const = 0;
};

// The module's codec, loaded on the first call. Throws std::runtime_error naming the module's file
// when it cannot be loaded.
const ImageCodec& image_codec();

}  // namespace lab::codec
