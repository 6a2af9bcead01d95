#include "film/image_output.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#include "common/input_error.hpp"
#include "film/atomic_file.hpp"
#include "common/file_extension.hpp"
#include "common/image_claim.hpp"
#include "common/image_codec.hpp"

namespace lab::film {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormats = "use .exr (linear float) or .png (8-bit sRGB)";
constexpr const char* kPrefix = "dtoadq:";

enum class FileFormat { Exr, Png, Other };

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

codec::Attribute text_attribute(const std::string& name, const std::string& text) {
    codec::Attribute a;
    a.name = name;
    a.text = text;
    return a;
}

// as_text: PNG text chunks hold strings only
void add_metadata(codec::Encoding& encoding, const ImageMetadata& metadata, bool as_text) {
    encoding.attributes.push_back(text_attribute("Software", metadata.software));
    for (const auto& [key, value] : metadata.values) {
        check_key(key);
        codec::Attribute a = text_attribute(kPrefix + key, metadata_text(value));
        if (!as_text && std::holds_alternative<int>(value)) {
            a.kind = codec::Attribute::Kind::integer;
            a.integer = std::get<int>(value);
        } else if (!as_text && std::holds_alternative<float>(value)) {
            a.kind = codec::Attribute::Kind::real;
            a.real = std::get<float>(value);
        }
        encoding.attributes.push_back(std::move(a));
    }
}

// Encodes the image in memory (format "openexr" or "png"), then writes the bytes atomically, so
// every failure of the disk is seen by write_file_atomically.
void encode_and_write(const std::string& path, const codec::Encoding& encoding) {
    std::vector<unsigned char> bytes;
    std::string error;
    if (!codec::image_codec().encode(path, encoding, &bytes, &error))
        throw InputError(path, "", "cannot encode " + encoding.format + ": " + error);
    write_file_atomically(path, bytes.data(), bytes.size());
}

std::unique_ptr<codec::ImageFile> open_image(const std::string& path) {
    std::string error;
    std::unique_ptr<codec::ImageFile> in = codec::image_codec().open(path, &error);
    if (!in) {
        std::error_code ec;
        if (!fs::exists(path, ec)) throw InputError(path, "", "cannot read: no such file");
        throw InputError(path, "", "cannot read: " + error);
    }
    return in;
}

int channel_index(const codec::Header& header, const std::string& name) {
    for (size_t c = 0; c < header.channel_names.size(); ++c)
        if (header.channel_names[c] == name) return int(c);
    return -1;
}

// All of the file's channels, as floats; the caller keeps `kept_per_pixel` floats a pixel of its own
// from them, which the claim check (common/image_claim.hpp) counts before anything is allocated.
std::vector<float> read_all_channels(const std::string& path, codec::ImageFile& in, size_t kept_per_pixel) {
    const codec::Header& h = in.header();
    codec::check_image_file_claim(path, h, h.channels + int(kept_per_pixel));
    std::vector<float> all(size_t(h.width) * size_t(h.height) * size_t(h.channels));
    std::string error;
    if (!in.read(h.channels, all.data(), &error)) throw InputError(path, "", "cannot read: " + error);
    return all;
}

}  // namespace

void check_output_path(const std::string& path) {
    if (!path.empty() && format_of(path) == FileFormat::Other) {
        const std::string ext = fs::path(path).extension().string();
        if (ext.empty()) throw InputError(path, "", std::string("no image extension: ") + kFormats);
        throw InputError(path, "", "unsupported image format \"" + ext + "\": " + kFormats);
    }
    check_writable(path);
    (void)codec::image_codec();  // a codec that cannot be loaded fails here too, before the render
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
    codec::Encoding encoding;
    encoding.format = "openexr";
    encoding.width = image.width;
    encoding.height = image.height;
    encoding.channels = int(channels);
    encoding.channel_names = {"R", "G", "B"};
    for (const ImageChannel& c : extra) encoding.channel_names.push_back(c.name);
    encoding.attributes = {text_attribute("oiio:ColorSpace", "Linear"), text_attribute("compression", "zip")};
    add_metadata(encoding, metadata, false);
    if (extra.empty()) {
        encoding.pixels = image.rgb.data();
        return encode_and_write(path, encoding);
    }
    std::vector<float> interleaved(pixels * channels);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) interleaved[p * channels + c] = image.rgb[p * 3 + c];
        for (size_t c = 0; c < extra.size(); ++c) interleaved[p * channels + 3 + c] = extra[c].values[p];
    }
    encoding.pixels = interleaved.data();
    encode_and_write(path, encoding);
}

void write_png(const std::string& path, const ImageRgb& image, ToneMap tone_map, float exposure_stops, const ImageMetadata& metadata) {
    check_image(image, "write_png");
    write_srgb8_png(path, image.width, image.height, to_srgb8(image, tone_map, exposure_stops), metadata);
}

void write_srgb8_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, const ImageMetadata& metadata) {
    if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3)
        throw std::invalid_argument("write_srgb8_png: " + std::to_string(rgb.size()) + " bytes for " + std::to_string(width) + "x" +
                                    std::to_string(height) + " pixels");
    check_writable(path);
    codec::Encoding encoding;
    encoding.format = "png";
    encoding.width = width;
    encoding.height = height;
    encoding.channels = 3;
    encoding.bytes = true;
    encoding.pixels = rgb.data();
    encoding.attributes = {text_attribute("oiio:ColorSpace", "sRGB")};  // an sRGB chunk: viewers apply no other gamma
    add_metadata(encoding, metadata, true);
    encode_and_write(path, encoding);
}

ImageRgb read_image(const std::string& path, ImageMetadata* metadata) {
    std::unique_ptr<codec::ImageFile> in = open_image(path);
    const codec::Header& h = in->header();
    if (h.format != "openexr" && h.format != "png") throw InputError(path, "", "is a " + h.format + " image; only OpenEXR and PNG are read");
    int channels[3] = {channel_index(h, "R"), channel_index(h, "G"), channel_index(h, "B")};
    if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
        if (h.channels != 1) throw InputError(path, "", "has no R, G, B channels");
        channels[0] = channels[1] = channels[2] = 0;  // grey
    }
    if (h.width <= 0 || h.height <= 0) throw InputError(path, "", "is empty");

    const std::vector<float> all = read_all_channels(path, *in, 3);
    ImageRgb image(h.width, h.height);
    const bool srgb = h.format == "png";
    for (size_t p = 0; p < image.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = all[p * size_t(h.channels) + size_t(channels[c])];
            image.rgb[p * 3 + size_t(c)] = srgb ? srgb_decode(v) : v;
        }

    if (metadata) {
        *metadata = ImageMetadata{};
        const std::string prefix = kPrefix;
        for (const codec::Attribute& a : h.attributes) {
            if (a.name == "Software" && a.kind == codec::Attribute::Kind::text) metadata->software = a.text;
            if (a.name.compare(0, prefix.size(), prefix) != 0) continue;
            const std::string key = a.name.substr(prefix.size());
            if (a.kind == codec::Attribute::Kind::integer)
                metadata->set(key, a.integer);
            else if (a.kind == codec::Attribute::Kind::real)
                metadata->set(key, a.real);
            else
                metadata->set(key, a.text);
        }
    }
    return image;
}

std::vector<ImageChannel> read_exr_channels(const std::string& path, const std::vector<std::string>& names, int* width, int* height) {
    std::unique_ptr<codec::ImageFile> in = open_image(path);
    const codec::Header& h = in->header();
    if (h.format != "openexr") throw InputError(path, "", "is not an OpenEXR file");
    std::vector<int> index;
    for (const std::string& name : names) {
        index.push_back(channel_index(h, name));
        if (index.back() < 0) throw InputError(path, name, "no such channel");
    }
    if (h.width <= 0 || h.height <= 0) throw InputError(path, "", "is empty");
    const size_t pixels = size_t(h.width) * size_t(h.height), channels = size_t(h.channels);
    const std::vector<float> all = read_all_channels(path, *in, names.size());
    std::vector<ImageChannel> out;
    for (size_t c = 0; c < names.size(); ++c) {
        ImageChannel channel{names[c], std::vector<float>(pixels)};
        for (size_t p = 0; p < pixels; ++p) channel.values[p] = all[p * channels + size_t(index[c])];
        out.push_back(std::move(channel));
    }
    *width = h.width;
    *height = h.height;
    return out;
}

}  // namespace lab::film
