// An emitter's image that may change with the scene time: a still image, a numbered sequence of
// images (a printf-style pattern, screen_%04d.exr, played at a given frame rate) or a video file
// (read through OpenImageIO's FFmpeg reader, which gives each frame as a subimage, with the file's
// frame rate). The frame shown at scene time t is floor(t * fps) (docs/scenes.md, "Time").
// render/emitter_images.hpp reads the frames.
#pragma once

#include <optional>
#include <string>

namespace lab::ibl {

struct FrameSource {
    enum class Kind { still, sequence, video };
    Kind kind = Kind::still;
    std::string path;      // the file, or the sequence's pattern
    double fps = 0.0;      // sequence: as the scene gives it; video: the file's own (open_video); still: 0
    long long frames = 0;  // video: how many it holds (open_video); sequence and still: 0 (a sequence ends at its first missing file)
};

// Whether `path` names a video file by its extension: one of ibl/radiance_image.hpp's kVideos
// (.mp4, .mov, .mkv, .avi, .webm).
bool is_video_path(const std::string& path);

// What `path` names, for the scene file `scene_file`'s fields `image_field` and `fps_field` (the
// messages' names), without opening a file:
//  - a pattern (common/frame_pattern.hpp) is a sequence, which needs `fps` in (0, 1000];
//  - a video file (is_video_path) is a video, whose rate is its own: `fps` must be absent;
//  - anything else is a still, and `fps` must be absent.
// Throws lab::InputError naming the scene file and the field for a misplaced, missing or bad fps.
FrameSource frame_source(const std::string& path, std::optional<double> fps, const std::string& scene_file, const std::string& image_field,
                         const std::string& fps_field);

// A video's frame count and rate, from its header. Throws lab::InputError naming the file when it
// cannot be opened, holds no frame or gives no rate in (0, 1000].
void open_video(FrameSource* source);

// The frame shown at scene time t: 0 for a still and for t <= 0, else floor(t * fps), where t * fps within
// 1e-9 (relative) of an integer counts as that integer, so that t = k / fps, as a sequence render
// sets it, shows frame k although k / fps * fps may round to just below k.
long long frame_at_time(const FrameSource& source, double t);

// The file that holds frame `frame` (a sequence's numbered file; a still's or a video's own path).
std::string frame_file(const FrameSource& source, long long frame);

}  // namespace lab::ibl
