// `dtoadq render SCENE --frames A:B --fps N -o out_%04d.exr [--video out.mp4]`: frames A to B-1 of
// the scene's animation (docs/scenes.md, "Time"), frame k at the scene time k / N. Each frame is a
// normal render (render_job.hpp) into its own EXR, with the frame number, the frame rate and the
// scene time in its metadata, so each can be resumed, merged or checked alone; the sequence
// resumes itself: a frame file that holds --spp samples is finished and skipped, one that holds
// fewer (an interrupted frame) is continued, a missing one rendered. --video then makes the frames'
// tone-mapped PNGs into a video with the ffmpeg program (common/ffmpeg.hpp).
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/render_job.hpp"

namespace lab::cli {

struct SequenceOptions {
    std::string frames;  // "A:B": frames A to B-1; empty: one render, no sequence
    double fps = 0.0;    // frames per second of scene time
    std::string video;   // .mp4 to make of the frames; empty: none
};

void add_sequence_options(CLI::App& cmd, const std::shared_ptr<SequenceOptions>& sequence);

// Checks everything first (the frames, the rate, the pattern, the options a sequence cannot take,
// FFmpeg for --video), then renders or resumes every frame that is not finished, in order; Ctrl-C
// stops in the frame in progress and writes it (the next run continues it). Throws lab::InputError
// for bad input, std::runtime_error when FFmpeg fails (the frames are kept).
void run_render_sequence(const RenderJobOptions& job, const RenderRunOptions& run, const SequenceOptions& sequence);

}  // namespace lab::cli
