// An emitter's image that may change with the scene time: a still image, a numbered sequence of
// images (a printf-style pattern, screen_%04d.exr, played at a given frame rate) or a video file
// (read through OpenImageIO's FFmpeg reader, which gives each frame as a subimage and the file's
// frame rate). The frame shown at scene time t is floor(t * fps) (docs/scenes.md, "Time"); every
// frame is read as linear RGB with the limits every image header is held to (common/image_claim.hpp).
#pragma once

#include <optional>
#include <string>

#include "film/image.hpp"

namespace lab::ibl {

struct FrameSource {
    enum class Kind { still, sequence, video };
    Kind kind = Kind::still;
    std::string path;         // the file, or the sequence's pattern
    double fps = 0.0;         // sequence: as given; video: the file's own; still: 0
    long long frames = 0;     // video: how many it holds; sequence and still: 0 (a sequence ends at its first missing file)
    int width = 0, height = 0;  // video: every frame's size; 0 for the others, whose files are read one at a time
};

// What `path` names, for the scene file `scene_file`'s fields `image_field` and `fps_field` (the
// messages' names):
//  - a pattern (common/frame_pattern.hpp) is a sequence, which needs a finite `fps` in (0, 1000];
//  - a file with a video extension (.mp4, .mov, .mkv, .avi, .webm) is a video, opened here for its
//    frame count and rate; `fps` must be absent, since a video's rate is its own;
//  - anything else is a still, and `fps` must be absent.
// Throws lab::InputError, one line, for a missing or unreadable video or a misplaced or bad fps.
FrameSource describe_frame_source(const std::string& path, std::optional<double> fps, const std::string& scene_file,
                                  const std::string& image_field, const std::string& fps_field);

// The frame shown at scene time t >= 0: 0 for a still, else floor(t * fps), where t * fps within
// 1e-9 (relative) of an integer counts as that integer, so that t = k / fps, as a sequence render
// sets it, shows frame k although k / fps * fps may round to just below k.
long long frame_at_time(const FrameSource& source, double t);

// The file that holds frame `frame` of a still or a sequence (a video's is its own path).
std::string frame_file(const FrameSource& source, long long frame);

// Frame `frame`, read as linear RGB (row by row from the top). 8-bit and 16-bit integer images and video frames are display-encoded and
// are decoded with the sRGB transfer function (IEC 61966-2-1); OpenEXR, Radiance HDR and float
// TIFFs are linear already. Grey images become RGB; channels past the third (alpha) are ignored.
// Throws lab::InputError naming the file (and the frame, for sequences and videos): a missing frame
// file, a frame past a video's end, an unreadable or corrupt file, a header that claims more than
// the file or the machine holds, a non-finite or negative texel.
film::ImageRgb read_frame(const FrameSource& source, long long frame);

}  // namespace lab::ibl
