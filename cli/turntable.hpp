// `dtoadq view --turntable N`: the test model (or a scene) turning on a turntable, or the
// environment turning around it, in N frames rendered headless at a given sample count, written
// as a frame sequence or made into a video with FFmpeg (docs/viewer.md).
#pragma once

#include <string>

#include "cli/render_job.hpp"

namespace lab::cli {

struct TurntableOptions {
    int frames = 0;                // one turn in this many frames
    std::string turn = "model";    // model: the model turns under fixed lighting; environment: the map turns around it
    int spp = 16;                  // per frame
    int fps = 30;                  // of the video
    std::string output;            // .mp4 (made by ffmpeg), or a frame pattern with one %d / %0Nd: NAME_%04d.png or .exr
    std::string tone_map = "aces";
    float exposure = 0.0f;
    bool quiet = false;
};

// Checks everything first (the options, the output, FFmpeg for a video), then renders and writes
// each frame as it is done; Ctrl-C stops after the frame in progress and keeps those done (a video
// is made of them). Throws lab::InputError for bad options, std::runtime_error when FFmpeg fails
// (the frames are then kept in a folder beside the video, named in the message).
void render_turntable(const RenderJobOptions& job_options, const TurntableOptions& options);

}  // namespace lab::cli
