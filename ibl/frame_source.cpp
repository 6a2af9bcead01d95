#include "ibl/frame_source.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>

#include "common/file_extension.hpp"
#include "common/frame_pattern.hpp"
#include "common/image_claim.hpp"
#include "common/image_codec.hpp"
#include "common/image_open.hpp"
#include "common/input_error.hpp"
#include "common/message_number.hpp"
#include "film/tone_map.hpp"

namespace lab::ibl {

namespace {

// An emitter's image is sampled texel by texel; past 16384 on a side its tables alone would hold
// gigabytes for what a screen in a scene shows.
constexpr int kMaxFrameSide = 16384;

bool is_video_path(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    return ext == ".mp4" || ext == ".mov" || ext == ".mkv" || ext == ".avi" || ext == ".webm";
}

const codec::Attribute* find_attribute(const codec::Header& header, const std::string& name) {
    for (const codec::Attribute& a : header.attributes)
        if (a.name == name) return &a;
    return nullptr;
}

// OpenImageIO gives a video's rate as the rational "num/den".
double rational_value(const codec::Attribute& a) {
    if (a.kind == codec::Attribute::Kind::integer) return double(a.integer);
    if (a.kind == codec::Attribute::Kind::real) return double(a.real);
    char* end = nullptr;
    const double num = std::strtod(a.text.c_str(), &end);
    if (end == a.text.c_str()) return 0.0;
    if (*end != '/') return num;
    const double den = std::strtod(end + 1, nullptr);
    return den > 0.0 ? num / den : 0.0;
}

std::unique_ptr<codec::ImageFile> open_image(const std::string& path, const std::string& what) {
    std::unique_ptr<codec::ImageFile> file = codec::open_flat_image(path, "an image", what);
    const codec::Header& h = file->header();
    if (h.width <= 0 || h.height <= 0 || h.width > kMaxFrameSide || h.height > kMaxFrameSide)
        throw InputError(path, "size", std::to_string(h.width) + " x " + std::to_string(h.height) + " is outside 1 to 16384 a side" + what);
    if (h.channels < 1) throw InputError(path, "channels", "none" + what);
    return file;
}

// Whether the pixels are display-encoded: integer data unless the file says it is linear, float
// data only when the file says it is sRGB.
bool is_display_encoded(const codec::Header& header) {
    const codec::Attribute* space = find_attribute(header, "oiio:ColorSpace");
    const std::string name = space && space->kind == codec::Attribute::Kind::text ? space->text : "";
    if (header.floating) return name == "sRGB";
    return name != "Linear" && name != "linear" && name != "scene_linear";
}

}  // namespace

FrameSource describe_frame_source(const std::string& path, std::optional<double> fps, const std::string& scene_file,
                                  const std::string& image_field, const std::string& fps_field) {
    FrameSource source;
    source.path = path;
    if (is_frame_pattern(path)) {
        source.kind = FrameSource::Kind::sequence;
        if (!fps) throw InputError(scene_file, fps_field, "missing: the sequence " + path + " needs its frames per second");
        if (!(std::isfinite(*fps) && *fps > 0.0 && *fps <= 1000.0))
            throw InputError(scene_file, fps_field, "must be in (0, 1000], got " + message_number(*fps));
        source.fps = *fps;
        return source;
    }
    if (fps) throw InputError(scene_file, fps_field, "only a sequence (a pattern such as screen_%04d.exr in " + image_field + ") has a frame rate to give");
    if (!is_video_path(path)) return source;

    source.kind = FrameSource::Kind::video;
    const std::unique_ptr<codec::ImageFile> file = open_image(path, " (the video of " + scene_file + "'s " + image_field + ")");
    const codec::Header& h = file->header();
    const codec::Attribute* frames = find_attribute(h, "oiio:subimages");
    const codec::Attribute* rate = find_attribute(h, "FramesPerSecond");
    source.frames = frames && frames->kind == codec::Attribute::Kind::integer ? frames->integer : 0;
    source.fps = rate ? rational_value(*rate) : 0.0;
    if (source.frames < 1) throw InputError(path, "frames", "none that can be read (the video of " + scene_file + "'s " + image_field + ")");
    if (!(std::isfinite(source.fps) && source.fps > 0.0 && source.fps <= 1000.0))
        throw InputError(path, "FramesPerSecond", "must be in (0, 1000], got " + message_number(source.fps));
    source.width = h.width;
    source.height = h.height;
    return source;
}

long long frame_at_time(const FrameSource& source, double t) {
    if (source.kind == FrameSource::Kind::still) return 0;
    const double x = t * source.fps;
    const double nearest = std::nearbyint(x);
    if (std::fabs(x - nearest) <= 1e-9 * std::fmax(1.0, std::fabs(x))) return (long long)nearest;
    return (long long)std::floor(x);
}

std::string frame_file(const FrameSource& source, long long frame) {
    return source.kind == FrameSource::Kind::sequence ? frame_path(source.path, frame) : source.path;
}

film::ImageRgb read_frame(const FrameSource& source, long long frame) {
    const std::string path = frame_file(source, frame);
    std::string what;
    if (source.kind == FrameSource::Kind::sequence) what = " (frame " + std::to_string(frame) + " of the sequence " + source.path + ")";
    if (source.kind == FrameSource::Kind::video) {
        what = " (frame " + std::to_string(frame) + ")";
        if (frame < 0 || frame >= source.frames)
            throw InputError(path, "frames", "frame " + std::to_string(frame) + " is past the video's end: it holds " + std::to_string(source.frames) +
                                                 " (" + message_number(double(source.frames) / source.fps) + " s at " + message_number(source.fps) + " fps)");
    }
    const std::unique_ptr<codec::ImageFile> file = open_image(path, what);
    const codec::Header& h = file->header();
    if (source.kind == FrameSource::Kind::video && (h.width != source.width || h.height != source.height))
        throw InputError(path, "size", "changed while the scene was rendered" + what);
    const int used = h.channels >= 3 ? 3 : 1;
    codec::check_image_file_claim(path, h, 3);  // the RGB frame; grey is read into its first third
    film::ImageRgb out(h.width, h.height);
    const size_t pixels = out.pixel_count();
    std::string error;
    const bool ok = source.kind == FrameSource::Kind::video ? file->read_subimage(int(frame), used, out.rgb.data(), &error)
                                                              : file->read(used, out.rgb.data(), &error);
    if (!ok) throw InputError(path, "pixels", "cannot be read (corrupt or truncated file)" + what);
    if (used == 1)  // spread grey over RGB, from the end so that no value is overwritten before it is read
        for (size_t p = pixels; p-- > 0;) out.rgb[p * 3] = out.rgb[p * 3 + 1] = out.rgb[p * 3 + 2] = out.rgb[p];
    const bool encoded = is_display_encoded(h);
    for (size_t i = 0; i < out.rgb.size(); ++i) {
        const float v = out.rgb[i];
        if (!std::isfinite(v) || v < 0.0f) {
            const size_t p = i / 3;
            throw InputError(path, "pixels", "texel (" + std::to_string(p % size_t(h.width)) + ", " + std::to_string(p / size_t(h.width)) +
                                                 ") is " + (std::isfinite(v) ? "negative" : "not finite") + ": emitted radiance is finite and >= 0" + what);
        }
        if (encoded) out.rgb[i] = film::srgb_decode(v);
    }
    return out;
}

}  // namespace lab::ibl
