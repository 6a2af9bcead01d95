#include "ibl/frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "common/file_extension.hpp"
#include "common/frame_pattern.hpp"
#include "common/image_codec.hpp"
#include "common/image_open.hpp"
#include "common/input_error.hpp"
#include "common/message_number.hpp"
#include "ibl/radiance_image.hpp"

namespace lab::ibl {

namespace {

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

}  // namespace

bool is_video_path(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    return std::any_of(kVideos.begin(), kVideos.end(), [&](const RadianceFormat& f) { return f.extension == ext; });
}

FrameSource frame_source(const std::string& path, std::optional<double> fps, const std::string& scene_file, const std::string& image_field,
                         const std::string& fps_field) {
    FrameSource source;
    source.path = path;
    if (is_frame_pattern(path)) {
        source.kind = FrameSource::Kind::sequence;
        if (!fps) throw InputError(scene_file, fps_field, "missing: the sequence in " + image_field + " needs its frames per second");
        if (!(std::isfinite(*fps) && *fps > 0.0 && *fps <= 1000.0))
            throw InputError(scene_file, fps_field, "must be in (0, 1000], got " + message_number(*fps));
        source.fps = *fps;
        return source;
    }
    if (fps)
        throw InputError(scene_file, fps_field,
                         "only a sequence (a pattern such as screen_%04d.exr in " + image_field + ") takes a frame rate; a video's is its own");
    if (is_video_path(path)) source.kind = FrameSource::Kind::video;
    return source;
}

void open_video(FrameSource* source) {
    const std::unique_ptr<codec::ImageFile> file = codec::open_flat_image(source->path, "a video", "");
    const codec::Header& h = file->header();
    const codec::Attribute* frames = find_attribute(h, "oiio:subimages");
    const codec::Attribute* rate = find_attribute(h, "FramesPerSecond");
    source->frames = frames && frames->kind == codec::Attribute::Kind::integer ? frames->integer : 0;
    source->fps = rate ? rational_value(*rate) : 0.0;
    if (source->frames < 1) throw InputError(source->path, "frames", "none that can be read");
    if (!(std::isfinite(source->fps) && source->fps > 0.0 && source->fps <= 1000.0))
        throw InputError(source->path, "FramesPerSecond", "must be in (0, 1000], got " + message_number(source->fps));
}

long long frame_at_time(const FrameSource& source, double t) {
    if (source.kind == FrameSource::Kind::still) return 0;
    const double x = t * source.fps;
    if (!(x > 0.0)) return 0;  // before the start, as keyframes hold their first value
    const double nearest = std::nearbyint(x);
    if (std::fabs(x - nearest) <= 1e-9 * std::fmax(1.0, std::fabs(x))) return (long long)nearest;
    return (long long)std::floor(x);
}

std::string frame_file(const FrameSource& source, long long frame) {
    return source.kind == FrameSource::Kind::sequence ? frame_path(source.path, frame) : source.path;
}

}  // namespace lab::ibl
