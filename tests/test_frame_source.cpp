// Emitter images that change with time (ibl/frame_source.hpp, render/emitter_images.hpp): the frame a
// scene time shows, a video read frame by frame against the PNG sequence it was encoded from, and
// every bad input refused with one line naming the file and the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "ibl/frame_source.hpp"
#include "render/emitter_images.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_time.hpp"

namespace {

using lab::ibl::FrameSource;

std::string frame_source_scratch() {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "dtoadq_frame_source_tests";
    std::filesystem::create_directories(folder);
    return folder.string();
}

template <class F>
std::string frame_source_error(F&& f) {
    try {
        f();
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

FrameSource source_of(const std::string& path, std::optional<double> fps = std::nullopt) {
    FrameSource s = lab::ibl::frame_source(path, fps, "room.json", "emitters[2].image", "emitters[2].fps");
    if (s.kind == FrameSource::Kind::video) lab::ibl::open_video(&s);
    return s;
}

}  // namespace

TEST_CASE("frame sources: t = k / fps shows frame k, and between frames the earlier one", "[ibl]") {
    // A rate that is not a whole number, as NTSC's: k / fps * fps falls just below k for many k, where
    // a plain floor would show the frame before the one the sequence render asked for.
    for (double fps : {12.0, 24.0, 30000.0 / 1001.0, 7.0, 1000.0, 0.5}) {
        FrameSource s;
        s.kind = FrameSource::Kind::sequence;
        s.fps = fps;
        int plain_floor_wrong = 0;
        for (long long k = 0; k < 20000; ++k) {
            const double t = double(k) / fps;
            REQUIRE(lab::ibl::frame_at_time(s, t) == k);
            if ((long long)std::floor(t * fps) != k) ++plain_floor_wrong;
            // half a frame later it is still frame k; a hundredth of a frame before, frame k - 1
            REQUIRE(lab::ibl::frame_at_time(s, (double(k) + 0.5) / fps) == k);
            if (k > 0) REQUIRE(lab::ibl::frame_at_time(s, (double(k) - 0.01) / fps) == k - 1);
        }
        if (fps == 30000.0 / 1001.0) CHECK(plain_floor_wrong > 0);  // the broken input: floor alone misses frames
    }
    FrameSource still;
    CHECK(lab::ibl::frame_at_time(still, 123.4) == 0);
    FrameSource sequence;
    sequence.kind = FrameSource::Kind::sequence;
    sequence.fps = 12.0;
    CHECK(lab::ibl::frame_at_time(sequence, -3.0) == 0);  // before the start, the first frame
}

TEST_CASE("frame sources: each frame of an mp4 is its PNG of the sequence, to the texel", "[ibl]") {
    const FrameSource video = source_of("scenes/tv_room/screen.mp4");
    REQUIRE(video.kind == FrameSource::Kind::video);
    CHECK(video.frames == 12);
    CHECK(video.fps == 12.0);
    const FrameSource sequence = source_of("scenes/tv_room/screen_%04d.png", 12.0);
    REQUIRE(sequence.kind == FrameSource::Kind::sequence);
    std::vector<brdf::float4> previous;
    for (long long k = 0; k < video.frames; ++k) {
        // the middle of frame k's time span
        const double t = (double(k) + 0.5) / 12.0;
        const lab::render::EmitterImage v = lab::render::load_emitter_image(video, t), p = lab::render::load_emitter_image(sequence, t);
        REQUIRE(v.width == 96);
        REQUIRE(v.height == 54);
        REQUIRE(p.width == v.width);
        REQUIRE(p.height == v.height);
        bool same = true, changed = k == 0;
        for (size_t i = 0; i < v.texels.size(); ++i) {
            same = same && v.texels[i].x == p.texels[i].x && v.texels[i].y == p.texels[i].y && v.texels[i].z == p.texels[i].z;
            if (k > 0) changed = changed || v.texels[i].x != previous[i].x || v.texels[i].y != previous[i].y || v.texels[i].z != previous[i].z;
        }
        CHECK(same);
        // each frame differs from the one before, so that reading frame 0 twelve times would fail
        CHECK(changed);
        previous = v.texels;
    }
    // the video's end and the sequence's missing file, each one line naming the file and the frame
    CHECK(frame_source_error([&] { lab::render::emitter_frame_file(video, 1.0); }) ==
          "scenes/tv_room/screen.mp4: frames: frame 12 at t = 1 s is past the video's end: it holds 12 (1 s at 12 fps)");
    CHECK(frame_source_error([&] { lab::render::emitter_frame_file(sequence, 1.0); }) ==
          "scenes/tv_room/screen_0012.png: no such file: frame 12 of the sequence scenes/tv_room/screen_%04d.png at t = 1 s");
}

TEST_CASE("frame sources: a misplaced or missing frame rate, a missing or false video: one line each", "[ibl]") {
    CHECK(frame_source_error([] { source_of("screen_%04d.png"); }) ==
          "room.json: emitters[2].fps: missing: the sequence in emitters[2].image needs its frames per second");
    CHECK(frame_source_error([] { source_of("screen_%04d.png", 0.0); }) == "room.json: emitters[2].fps: must be in (0, 1000], got 0");
    CHECK(frame_source_error([] { source_of("screen_%04d.png", 1001.0); }) == "room.json: emitters[2].fps: must be in (0, 1000], got 1001");
    const std::string only = "room.json: emitters[2].fps: only a sequence (a pattern such as screen_%04d.exr in emitters[2].image) takes a frame rate; a video's is its own";
    CHECK(frame_source_error([] { source_of("screen.png", 24.0); }) == only);
    CHECK(frame_source_error([] { source_of("scenes/tv_room/screen.mp4", 24.0); }) == only);
    CHECK(frame_source_error([] { source_of("no_such.mp4"); }) == "no_such.mp4: no such file");
    const std::string fake = frame_source_scratch() + "/fake.mp4";
    std::ofstream(fake, std::ios::binary) << "not a video at all";
    CHECK(frame_source_error([&] { source_of(fake); }) == fake + ": cannot be read as a video");
}

TEST_CASE("frame sources: a scene whose screen plays a sequence is animated, and its frames are checked", "[ibl][scene]") {
    const lab::scene::Scene room = lab::scene::load_scene("scenes/tv_room.json");
    CHECK(lab::scene::is_animated(room));
    lab::render::check_emitter_frames(room, 0, 12, 12.0);  // frames 0 to 11: every file there
    CHECK(frame_source_error([&] { lab::render::check_emitter_frames(room, 10, 14, 12.0); }) ==
          "scenes/tv_room.json: emitters[0].image: scenes/tv_room/screen_0012.png: no such file: frame 12 of the sequence "
          "scenes/tv_room/screen_%04d.png at t = 1 s");
    lab::scene::Scene still = room;
    still.emitters[0].image = "scenes/tv_room/screen_0003.png";
    still.emitters[0].image_fps.reset();
    CHECK_FALSE(lab::scene::is_animated(still));
}
