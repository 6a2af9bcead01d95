#include "film/image_output.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include "common/input_error.hpp"
#include "film/atomic_file.hpp"

namespace lab::film {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormats = "use .exr (linear float) or .png (8-bit sRGB)";
constexpr const char* kPrefix = "dtoadq:";

enum class FileFormat { Exr, Png, Other };

std::string lowercase_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

FileFormat format_of(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".exr") return FileFormat::Exr;
    if (ext == ".png") return FileFormat::Png;
    return FileFormat::Other;
}

// The folder exists and can take a new file, and PATH is not a folder or a read-only file.
void check_writable(const std::string& path) {
    if (path.empty()) throw InputError("command line", "", "the output image path is empty");
    const fs::path p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw InputError(path, "", "is a folder, not a file");
    const fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (!fs::is_directory(folder, ec)) throw InputError(path, "", "cannot write: folder " + folder.string() + " does not exist");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(path, "", "cannot write: folder " + folder.string() + ": " + std::strerror(errno));
    // the rename would replace a read-only file; refuse, as cp would
    if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0) throw InputError(path, "", std::string("cannot write: ") + std::strerror(errno));
}

void check_image(const ImageRgb& image, const char* what) {
    if (!image.valid())
        throw std::invalid_argument(std::string(what) + ": the image's sizes (" + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ") do not match its " + std::to_string(image.rgb.size()) + " floats");
}

void check_key(const std::string& key) {
    bool ok = !key.empty() && key.size() <= 64;
    for (unsigned char c : key) ok = ok && (std::isalnum(c) || c == '_' || c == '-' || c == '.');
    if (!ok) throw std::invalid_argument("image metadata: bad key \"" + key + "\" (letters, digits, _ - . only)");
}

// as_text: PNG text chunks hold strings only
void add_metadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata, bool as_text) {
    spec.attribute("Software", metadata.software);
    for (const auto& [key, value] : metadata.values) {
        check_key(key);
        const std::string name = kPrefix + key;
        if (as_text || std::holds_alternative<std::string>(value))
            spec.attribute(name, metadata_text(value));
        else if (const int* i = std::get_if<int>(&value))
            spec.attribute(name, *i);
        else
            spec.attribute(name, std::get<float>(value));
    }
}

// Encodes the image in memory with OpenImageIO (format "openexr" or "png"), then writes the bytes
// atomically, so every failure of the disk is seen by write_file_atomically.
void encode_and_write(const std::string& path, const char* format, const OIIO::ImageSpec& spec, const void* pixels) {
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(format);
    if (!out) throw std::runtime_error(std::string("OpenImageIO has no ") + format + " writer: " + OIIO::geterror());
    bool ok = out->set_ioproxy(&memory) && out->open(path, spec) && out->write_image(spec.format, pixels);
    ok = out->close() && ok;
    if (!ok) throw InputError(path, "", "cannot encode " + std::string(format) + ": " + out->geterror());
    write_file_atomically(path, bytes.data(), bytes.size());
}

std::unique_ptr<OIIO::ImageInput> open_image(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        std::error_code ec;
        if (!fs::exists(path, ec)) throw InputError(path, "", "cannot read: no such file");
        throw InputError(path, "", "cannot read: " + OIIO::geterror());
    }
    return in;
}

}  // namespace

void check_output_path(const std::string& path) {
    if (!path.empty() && format_of(path) == FileFormat::Other) {
        const std::string ext = fs::path(path).extension().string();
        if (ext.empty()) throw InputError(path, "", std::string("no image extension: ") + kFormats);
        throw InputError(path, "", "unsupported image format \"" + ext + "\": " + kFormats);
    }
    check_writable(path);
}

void write_image(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata) {
    check_output_path(path);
    if (format_of(path) == FileFormat::Exr)
        write_exr(path, image, metadata);
    else
        write_png(path, image, tone_map, exposure_stops, metadata);
}

void write_exr(const std::string& path, const ImageRgb& image, const ImageMetadata& metadata, const std::vector<ImageChannel>& extra) {
    check_image(image, "write_exr");
    check_writable(path);
    const size_t pixels = image.pixel_count(), channels = 3 + extra.size();
    for (const ImageChannel& c : extra)
        if (c.values.size() != pixels || c.name.empty())
            throw std::invalid_argument("write_exr: channel \"" + c.name + "\" has " + std::to_string(c.values.size()) + " values for " +
                                        std::to_string(pixels) + " pixels");
    OIIO::ImageSpec spec(image.width, image.height, int(channels), OIIO::TypeDesc::FLOAT);
    spec.channelnames.resize(3);  // the constructor names them R, G, B, A, channel4...
    spec.alpha_channel = -1;
    for (const ImageChannel& c : extra) spec.channelnames.push_back(c.name);
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("compression", "zip");
    add_metadata(spec, metadata, false);
    if (extra.empty()) return encode_and_write(path, "openexr", spec, image.rgb.data());
    std::vector<float> interleaved(pixels * channels);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) interleaved[p * channels + c] = image.rgb[p * 3 + c];
        for (size_t c = 0; c < extra.size(); ++c) interleaved[p * channels + 3 + c] = extra[c].values[p];
    }
    encode_and_write(path, "openexr", spec, interleaved.data());
}

void write_png(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata) {
    check_image(image, "write_png");
    check_writable(path);
    const std::vector<uint8_t> pixels = to_srgb8(image, tone_map, exposure_stops);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");  // an sRGB chunk: viewers apply no other gamma
    add_metadata(spec, metadata, true);
    encode_and_write(path, "png", spec, pixels.data());
}

ImageRgb read_image(const std::string& path, ImageMetadata* metadata) {
    std::unique_ptr<OIIO::ImageInput> in = open_image(path);
    const std::string format = in->format_name();
    if (format != "openexr" && format != "png") throw InputError(path, "", "is a " + format + " image; only OpenEXR and PNG are read");
    const OIIO::ImageSpec& spec = in->spec();
    int channels[3] = {spec.channelindex("R"), spec.channelindex("G"), spec.channelindex("B")};
    if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
        if (spec.nchannels != 1) throw InputError(path, "", "has no R, G, B channels");
        channels[0] = channels[1] = channels[2] = 0;  // grey
    }
    if (spec.width <= 0 || spec.height <= 0) throw InputError(path, "", "is empty");

    std::vector<float> all(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw InputError(path, "", "cannot read: " + in->geterror());
    ImageRgb image(spec.width, spec.height);
    const bool srgb = format == "png";
    for (size_t p = 0; p < image.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = all[p * size_t(spec.nchannels) + size_t(channels[c])];
            image.rgb[p * 3 + size_t(c)] = srgb ? srgb_decode(v) : v;
        }

    if (metadata) {
        *metadata = ImageMetadata{};
        metadata->software = spec.get_string_attribute("Software");
        const std::string prefix = kPrefix;
        for (const OIIO::ParamValue& p : spec.extra_attribs) {
            const std::string name = p.name().string();
            if (name.compare(0, prefix.size(), prefix) != 0) continue;
            const std::string key = name.substr(prefix.size());
            if (p.type() == OIIO::TypeDesc::INT)
                metadata->set(key, p.get_int());
            else if (p.type() == OIIO::TypeDesc::FLOAT)
                metadata->set(key, p.get_float());
            else
                metadata->set(key, p.get_string());
        }
    }
    return image;
}

std::vector<ImageChannel> read_exr_channels(const std::string& path, const std::vector<std::string>& names, int* width, int* height) {
    std::unique_ptr<OIIO::ImageInput> in = open_image(path);
    if (std::string(in->format_name()) != "openexr") throw InputError(path, "", "is not an OpenEXR file");
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<int> index;
    for (const std::string& name : names) {
        index.push_back(spec.channelindex(name));
        if (index.back() < 0) throw InputError(path, name, "no such channel");
    }
    if (spec.width <= 0 || spec.height <= 0) throw InputError(path, "", "is empty");
    const size_t pixels = size_t(spec.width) * size_t(spec.height), channels = size_t(spec.nchannels);
    std::vector<float> all(pixels * channels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw InputError(path, "", "cannot read: " + in->geterror());
    std::vector<ImageChannel> out;
    for (size_t c = 0; c < names.size(); ++c) {
        ImageChannel channel{names[c], std::vector<float>(pixels)};
        for (size_t p = 0; p < pixels; ++p) channel.values[p] = all[p * channels + size_t(index[c])];
        out.push_back(std::move(channel));
    }
    *width = spec.width;
    *height = spec.height;
    return out;
}

}  // namespace lab::film
