// FFmpeg, the program (Debian's ffmpeg; tools/install-deps.sh installs it): whether it runs, and a
// frame sequence made into a video.
#pragma once

#include <string>

namespace lab {

// Whether `ffmpeg -version` runs (it is on PATH and starts).
bool ffmpeg_available();

// Encodes the images of `frame_pattern` (common/frame_pattern.hpp: PNGs, or anything FFmpeg reads),
// from frame `first_frame` on while they exist, at `fps` frames per second, into an H.264 MP4 that
// any player plays (yuv420p, odd sizes padded to even), FFmpeg's output going to `log`. The video is
// written under a temporary name beside `output` and renamed when complete, so a failure leaves no
// partial file; it throws std::runtime_error "ffmpeg failed (status N): LAST LOG LINE".
void encode_video(const std::string& frame_pattern, long long first_frame, double fps, const std::string& output, const std::string& log);

}  // namespace lab
