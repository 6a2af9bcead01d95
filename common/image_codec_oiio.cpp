// common/image_codec.hpp with OpenImageIO: the module libdtoadq_image_codec.so, loaded on first use.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "common/image_codec.hpp"

namespace lab::codec {

namespace {

std::vector<Attribute> attributes_of(const OIIO::ImageSpec& spec) {
    std::vector<Attribute> out;
    for (const OIIO::ParamValue& p : spec.extra_attribs) {
        Attribute a;
        a.name = p.name().string();
        if (p.type() == OIIO::TypeDesc::INT) {
            a.kind = Attribute::Kind::integer;
            a.integer = p.get_int();
        } else if (p.type() == OIIO::TypeDesc::FLOAT) {
            a.kind = Attribute::Kind::real;
            a.real = p.get_float();
        } else {
            a.text = p.get_string();
        }
        out.push_back(std::move(a));
    }
    return out;
}

class OiioFile final : public ImageFile {
public:
    explicit OiioFile(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {
        const OIIO::ImageSpec& spec = in_->spec();
        header_.format = in_->format_name();
        header_.width = spec.width;
        header_.height = spec.height;
        header_.channels = spec.nchannels;
        header_.deep = spec.deep;
        header_.floating = spec.format.is_floating_point();
        for (int c = 0; c < spec.nchannels; ++c) header_.channel_names.push_back(spec.channel_name(c));
        header_.attributes = attributes_of(spec);
    }
    const Header& header() const override { return header_; }
    bool read(int channels, float* pixels, std::string* error) override { return read_subimage(0, channels, pixels, error); }
    bool read_subimage(int index, int channels, float* pixels, std::string* error) override {
        if (in_->read_image(index, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels)) return true;
        *error = in_->geterror();
        return false;
    }

private:
    std::unique_ptr<OIIO::ImageInput> in_;
    Header header_;
};

class OiioCodec final : public ImageCodec {
public:
    std::unique_ptr<ImageFile> open(const std::string& path, std::string* error) const override {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
        if (!in) {
            *error = OIIO::geterror();
            return nullptr;
        }
        return std::make_unique<OiioFile>(std::move(in));
    }

    // Encodes in memory (an IOVecOutput proxy), so that the caller writes the file atomically.
    bool encode(const std::string& path, const Encoding& image, std::vector<unsigned char>* file, std::string* error) const override {
        const OIIO::TypeDesc type = image.bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
        if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
        spec.alpha_channel = -1;  // the lab writes no alpha
        for (const Attribute& a : image.attributes) {
            if (a.kind == Attribute::Kind::integer)
                spec.attribute(a.name, a.integer);
            else if (a.kind == Attribute::Kind::real)
                spec.attribute(a.name, a.real);
            else
                spec.attribute(a.name, a.text);
        }
        std::unique_ptr<OIIO::ImageOutput> out = image.format.empty() ? OIIO::ImageOutput::create(path) : OIIO::ImageOutput::create(image.format);
        if (!out) {
            *error = "OpenImageIO has no writer for it: " + OIIO::geterror();
            return false;
        }
        OIIO::Filesystem::IOVecOutput memory(*file);
        bool ok = out->set_ioproxy(&memory) && out->open(path, spec) && out->write_image(type, image.pixels);
        ok = out->close() && ok;
        if (!ok) *error = out->geterror();
        return ok;
    }
};

}  // namespace

}  // namespace lab::codec

// The module's one entry point, looked up by name (common/image_codec_loader.cpp).
extern "C" __attribute__((visibility("default"))) const lab::codec::ImageCodec* dtoadq_image_codec() {
    static const lab::codec::OiioCodec codec;
    return &codec;
}
