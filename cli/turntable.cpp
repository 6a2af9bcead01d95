#include "cli/turntable.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <unistd.h>

#include "common/child_process.hpp"
#include "common/ffmpeg.hpp"
#include "common/frame_pattern.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "render/interrupt.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

namespace {

constexpr float kPi = 3.14159265358979f;

// The camera orbited by `degrees` about the vertical axis (+y) through its look-at point: a turn
// of the world about that axis seen from the camera's side.
scene::Camera orbited(scene::Camera c, float degrees) {
    const float a = degrees * kPi / 180.0f, cs = std::cos(a), sn = std::sin(a);
    auto turn = [&](scene::Vec3 v) { return scene::Vec3(cs * v.x + sn * v.z, v.y, -sn * v.x + cs * v.z); };
    c.position = c.look_at + turn(c.position - c.look_at);
    c.up = turn(c.up);
    return c;
}

}  // namespace

void render_turntable(const RenderJobOptions& job_options, const TurntableOptions& t) {
    if (t.frames < 1 || t.frames > 100000) throw InputError("--turntable", "", "must be a number of frames in [1, 100000]");
    if (t.turn != "model" && t.turn != "environment") throw InputError("--turn", "", "expected model or environment, got \"" + t.turn + "\"");
    if (t.spp < 1 || t.spp > 1 << 24) throw InputError("--spp", "", "must be in [1, 16777216]");
    if (t.fps < 1 || t.fps > 240) throw InputError("--fps", "", "must be in [1, 240]");
    const film::ToneMap tone_map = film::parse_tone_map(t.tone_map);
    if (!(t.exposure >= -64.0f && t.exposure <= 64.0f)) throw InputError("--exposure", "", "must be a number of stops in [-64, 64]");
    if (t.output.empty()) throw InputError("--output", "", "--turntable needs -o: a video (.mp4) or a frame pattern (frame_%04d.png or .exr)");
    const bool video = fs::path(t.output).extension() == ".mp4";
    std::optional<TempFolder> frames_folder;
    std::string pattern = t.output;
    if (video) {
        const fs::path folder = fs::path(t.output).parent_path().empty() ? fs::path(".") : fs::path(t.output).parent_path();
        if (!fs::is_directory(folder) || access(folder.c_str(), W_OK) != 0)
            throw InputError(t.output, "", "cannot write the video: " + folder.string() + " is not a folder this user can write");
        if (!ffmpeg_available())
            throw InputError("--turntable", "", "a video needs FFmpeg (apt-get install ffmpeg); or write the frames: -o frame_%04d.png");
        frames_folder.emplace("turntable");
        pattern = (frames_folder->path() / "frame_%05d.png").string();
    } else {
        if (!is_frame_pattern(t.output))
            throw InputError(t.output, "", "expected a video (.mp4) or a frame pattern with one %d or %0Nd (frame_%04d.png or .exr)");
        film::check_output_path(frame_path(t.output, 0));
    }

    RenderJob job = prepare_render_job(job_options);
    std::optional<opencl::Runtime> runtime;
    std::unique_ptr<render::Renderer> renderer = make_renderer(job, job_options.device, &runtime);
    const scene::Camera camera = job.input.scene.camera;
    const bool environment = job.input.environment.has_value();
    const float rotation = environment ? job.input.environment->rotation_degrees() : 0.0f;
    const float exposure = environment ? job.input.environment->exposure_stops() : 0.0f;
    if (t.turn == "environment" && !environment) throw InputError("--turn", "", "environment: the render has no environment to turn");

    render::InterruptScope interrupt_scope;
    int done = 0;
    for (int k = 0; k < t.frames && !render::interrupt_requested(); ++k) {
        const float angle = 360.0f * float(k) / float(t.frames);
        // The model turning by +angle under fixed lighting is, seen from the camera, the camera and
        // the environment turning by -angle about the same axis.
        if (t.turn == "model") {
            renderer->set_camera(orbited(camera, -angle));
            if (environment) renderer->set_environment_transform(rotation - angle, exposure);
        } else {
            renderer->set_environment_transform(rotation + angle, exposure);
        }
        renderer->add_samples(t.spp);
        film::ImageMetadata metadata = job_metadata(job, *renderer, renderer->statistics());
        metadata.set("turntable", t.turn);
        metadata.set("turntable_frame", k);
        metadata.set("turntable_degrees", angle);
        const std::string path = frame_path(pattern, k);
        film::write_image(path, renderer->image(), tone_map, t.exposure, metadata);
        ++done;
        if (!t.quiet) std::printf("frame %d/%d (%.1f deg): %s\n", k + 1, t.frames, angle, video ? "rendered" : path.c_str());
        std::fflush(stdout);
    }
    if (video && done > 0) {
        // Into the output's folder under a temporary name, then renamed: a failed encode leaves no
        // partial video, and the frames are kept beside it.
        const fs::path log = frames_folder->path() / "ffmpeg.log";
        try {
            encode_video(pattern, 0, t.fps, t.output, log.string());
        } catch (const std::runtime_error& e) {
            std::error_code ec;
            const fs::path kept = t.output + ".frames";
            fs::remove_all(kept, ec);
            fs::copy(frames_folder->path(), kept, ec);
            throw std::runtime_error(std::string(e.what()) + "; the frames are kept in " + kept.string());
        }
        std::printf("wrote %s: %d frames at %d frames/s\n", t.output.c_str(), done, t.fps);
    }
    if (render::interrupt_requested()) {
        std::fprintf(stderr, "dtoadq: interrupted after %d of %d frames; those were written\n", done, t.frames);
        throw CLI::RuntimeError(render::kInterruptedExitStatus);
    }
}

}  // namespace lab::cli
