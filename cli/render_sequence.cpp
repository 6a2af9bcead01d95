#include "cli/render_sequence.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "common/child_process.hpp"
#include "common/ffmpeg.hpp"
#include "common/frame_pattern.hpp"
#include "common/input_error.hpp"
#include "render/emitter_images.hpp"
#include "render/interrupt.hpp"
#include "render/progressive.hpp"
#include "render/sample_ranges.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_time.hpp"
#include "scene/test_model.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

namespace {

std::string number_text(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

}  // namespace

void add_sequence_options(CLI::App& cmd, const std::shared_ptr<SequenceOptions>& sequence) {
    cmd.add_option("--frames", sequence->frames,
                   "A:B renders frames A to B-1 of the scene's animation, frame k at the scene time k / --fps, each into its own EXR "
                   "(-o a pattern with one %d or %0Nd: out_%04d.exr); a frame file that holds --spp samples is skipped, one with fewer "
                   "continued");
    cmd.add_option("--fps", sequence->fps, "With --frames: frames per second of scene time");
    cmd.add_option("--video", sequence->video,
                   "With --frames: also make the frames' tone-mapped PNGs into this H.264 video (.mp4) with the ffmpeg program");
}

void run_render_sequence(const RenderJobOptions& job, const RenderRunOptions& run, const SequenceOptions& sequence) {
    int64_t first = 0, end = 0;
    if (!render::parse_index_pair(sequence.frames, &first, &end))
        throw InputError("--frames", "", "expected A:B, frame numbers with 0 <= A < B (frames A to B-1), got \"" + sequence.frames + "\"");
    if (!(sequence.fps > 0.0 && sequence.fps <= 1000.0)) throw InputError("--fps", "", "--frames needs the frames per second of scene time, in (0, 1000]");
    check_frame_pattern(run.output, "the output of --frames");
    if (!render::is_exr_path(run.output))
        throw InputError(run.output, "", "a sequence writes EXRs (out_%04d.exr), whose film lets an interrupted frame resume; the PNG goes beside each");
    if (run.time_seconds > 0.0)
        throw InputError("--time", "", "a sequence renders --spp samples per frame, so that a frame file says whether it is finished: leave out --time");
    if (!run.samples.empty()) throw InputError("--samples", "", "cannot be used with --frames (split a sequence across machines by frames)");
    if (!run.resume.empty()) throw InputError("--resume", "", "--frames resumes by itself: it continues each frame file that holds fewer than --spp samples");
    if (job.scene_time != 0.0) throw InputError("--scene-time", "", "--frames gives each frame its time (frame / --fps): leave out --scene-time");
    if (!sequence.video.empty()) {
        if (fs::path(sequence.video).extension() != ".mp4") throw InputError(sequence.video, "", "--video writes an H.264 video: expected an .mp4");
        if (!ffmpeg_available())
            throw InputError("--video", "", "needs the ffmpeg program, which did not run (sh tools/install-deps.sh installs it): nothing was "
                                            "rendered and the frame files are as they were; without --video the frames render alone");
    }
    render::check_render_output(frame_path(run.output, first));  // and the PNG beside it
    // a time where a spline takes the camera out of its range stops the sequence before its first frame,
    const scene::Scene scene = job.scene.empty() ? scene::load_test_model() : scene::load_scene(job.scene);
    // and so does a frame an emitter's image sequence or video lacks
    for (int64_t k = first; k < end; ++k) scene::scene_at_time(scene, double(k) / sequence.fps);
    render::check_emitter_frames(scene, first, end, sequence.fps);

    render::InterruptScope interrupt_scope;  // a Ctrl-C between two frames stops the sequence too
    std::optional<opencl::Runtime> runtime;  // one program for every frame
    RenderJobOptions frame_job = job;
    frame_job.environment_cache = std::make_shared<EnvironmentCache>();  // and one environment, turned for each
    int rendered = 0, continued = 0, finished = 0;
    for (int64_t k = first; k < end; ++k) {
        if (render::interrupt_requested()) {
            if (k == first)
                std::fprintf(stderr, "dtoadq: interrupted before the first frame; nothing was written\n");
            else
                std::fprintf(stderr, "dtoadq: interrupted before frame %lld; frames %lld to %lld are written\n", (long long)k, (long long)first,
                             (long long)k - 1);
            throw CLI::RuntimeError(render::kInterruptedExitStatus);
        }
        frame_job.scene_time = double(k) / sequence.fps;
        RenderRunOptions frame_run = run;
        frame_run.output = frame_path(run.output, k);
        frame_run.skip_finished = true;
        std::error_code ec;
        if (fs::exists(frame_run.output, ec)) frame_run.resume = frame_run.output;
        film::ImageMetadata extra;
        extra.set("frame", int(k));
        extra.set("fps", number_text(sequence.fps));
        if (!run.quiet) std::printf("frame %lld (t = %s s)\n", (long long)k, number_text(frame_job.scene_time).c_str());
        std::fflush(stdout);
        if (run_render_job(frame_job, frame_run, extra, &runtime)) {
            ++(frame_run.resume.empty() ? rendered : continued);
        } else {
            ++finished;
            if (!run.quiet) std::printf("frame %lld: %s is finished (--spp %d), skipped\n", (long long)k, frame_run.output.c_str(), run.spp);
        }
    }
    std::printf("frames %lld to %lld: %d rendered, %d continued, %d finished before\n", (long long)first, (long long)end - 1, rendered, continued,
                finished);
    if (sequence.video.empty()) return;
    TempFolder log_folder("video");
    const std::string log = (log_folder.path() / "ffmpeg.log").string();
    try {
        encode_video(render::png_beside(run.output), first, sequence.fps, sequence.video, log);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string(e.what()) + "; the frames are kept (" + render::png_beside(run.output) + ")");
    }
    std::printf("wrote %s: %lld frames at %s frames/s\n", sequence.video.c_str(), (long long)(end - first), number_text(sequence.fps).c_str());
}

}  // namespace lab::cli
