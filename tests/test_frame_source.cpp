// Emitter images that change with time (ibl/frame_source.hpp): the frame a scene time shows, a video
// read frame by frame against the PNG sequence it was encoded from, the colour decoding, and every
// bad input refused with one line naming the file and the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "common/image_codec.hpp"
#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "ibl/frame_source.hpp"

namespace {

using lab::ibl::FrameSource;

std::filesystem::path frame_source_scratch() {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "dtoadq_frame_source_tests";
    std::filesystem::create_directories(folder);
    return folder;
}

// width x height x channels floats encoded by the image codec: 8-bit for .png, float otherwise.
std::string frame_source_write(const std::string& name, int width, int height, int channels, const std::vector<float>& pixels) {
    const std::string path = (frame_source_scratch() / name).string();
    lab::codec::Encoding e;
    e.width = width;
    e.height = height;
    e.channels = channels;
    const bool png = name.size() > 4 && name.substr(name.size() - 4) == ".png";
    std::vector<unsigned char> bytes;
    if (png) {
        for (float v : pixels) bytes.push_back((unsigned char)std::lround(v * 255.0f));
        e.bytes = true;
        e.pixels = bytes.data();
    } else {
        e.pixels = pixels.data();
    }
    std::vector<unsigned char> file;
    std::string error;
    REQUIRE(lab::codec::image_codec().encode(path, e, &file, &error));
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
    return path;
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

FrameSource describe(const std::string& path, std::optional<double> fps = std::nullopt) {
    return lab::ibl::describe_frame_source(path, fps, "room.json", "emitters[2].image", "emitters[2].fps");
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
}

TEST_CASE("frame sources: each frame of an mp4 is its PNG of the sequence, to the byte", "[ibl]") {
    const FrameSource video = describe("scenes/tv_room/screen.mp4");
    REQUIRE(video.kind == FrameSource::Kind::video);
    CHECK(video.frames == 12);
    CHECK(video.fps == 12.0);
    CHECK(video.width == 96);
    CHECK(video.height == 54);
    const FrameSource sequence = describe("scenes/tv_room/screen_%04d.png", 12.0);
    REQUIRE(sequence.kind == FrameSource::Kind::sequence);
    std::vector<float> previous;
    for (long long k = 0; k < video.frames; ++k) {
        const lab::film::ImageRgb v = lab::ibl::read_frame(video, k), p = lab::ibl::read_frame(sequence, k);
        REQUIRE(v.width == 96);
        REQUIRE(p.width == 96);
        REQUIRE(v.height == p.height);
        CHECK(v.rgb == p.rgb);
        // each frame differs from the one before, so that reading frame 0 twelve times would fail
        if (k > 0) CHECK(v.rgb != previous);
        previous = v.rgb;
    }
    CHECK(frame_source_error([&] { lab::ibl::read_frame(video, 12); }) ==
          "scenes/tv_room/screen.mp4: frames: frame 12 is past the video's end: it holds 12 (1 s at 12 fps)");
    CHECK(frame_source_error([&] { lab::ibl::read_frame(sequence, 12); }) ==
          "scenes/tv_room/screen_0012.png: no such file (frame 12 of the sequence scenes/tv_room/screen_%04d.png)");
}

TEST_CASE("frame sources: 8-bit images are decoded from sRGB, floats are linear, grey becomes RGB", "[ibl]") {
    const std::string png = frame_source_write("grey.png", 2, 1, 1, {128.0f / 255.0f, 1.0f});
    const lab::film::ImageRgb g = lab::ibl::read_frame(describe(png), 0);
    REQUIRE(g.rgb.size() == 6);
    for (int c = 0; c < 3; ++c) {
        CHECK(g.rgb[size_t(c)] == lab::film::srgb_decode(128.0f / 255.0f));
        CHECK(g.rgb[size_t(3 + c)] == 1.0f);
    }
    CHECK(g.rgb[0] == Approx(0.2158605).epsilon(1e-5));  // IEC 61966-2-1 at code 128
    const std::string exr = frame_source_write("linear.exr", 1, 1, 4, {0.5f, 2.0f, 40.0f, 0.25f});
    const lab::film::ImageRgb l = lab::ibl::read_frame(describe(exr), 0);
    CHECK(l.rgb == std::vector<float>{0.5f, 2.0f, 40.0f});
}

TEST_CASE("frame sources: bad input is one line naming the file and the field", "[ibl]") {
    CHECK(frame_source_error([] { describe("screen_%04d.png"); }) == "room.json: emitters[2].fps: missing: the sequence screen_%04d.png needs its frames per second");
    CHECK(frame_source_error([] { describe("screen_%04d.png", 0.0); }) == "room.json: emitters[2].fps: must be in (0, 1000], got 0");
    CHECK(frame_source_error([] { describe("screen_%04d.png", std::nan("")); }) == "room.json: emitters[2].fps: must be in (0, 1000], got nan");
    CHECK(frame_source_error([] { describe("screen.png", 24.0); }) ==
          "room.json: emitters[2].fps: only a sequence (a pattern such as screen_%04d.exr in emitters[2].image) has a frame rate to give");
    CHECK(frame_source_error([] { describe("scenes/tv_room/screen.mp4", 24.0); }).find("emitters[2].fps: only a sequence") != std::string::npos);
    CHECK(frame_source_error([] { describe("no_such.mp4"); }) == "no_such.mp4: no such file (the video of room.json's emitters[2].image)");

    const std::string corrupt = (frame_source_scratch() / "corrupt.png").string();
    std::ofstream(corrupt, std::ios::binary) << "\x89PNG\r\n\x1a\nnot really";
    CHECK(frame_source_error([&] { lab::ibl::read_frame(describe(corrupt), 0); }) == corrupt + ": cannot be read as an image");
    const std::string fake_video = (frame_source_scratch() / "fake.mp4").string();
    std::ofstream(fake_video, std::ios::binary) << "not a video at all";
    CHECK(frame_source_error([&] { describe(fake_video); }) == fake_video + ": cannot be read as an image (the video of room.json's emitters[2].image)");

    const std::string negative = frame_source_write("negative.exr", 3, 2, 3, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0});
    CHECK(frame_source_error([&] { lab::ibl::read_frame(describe(negative), 0); }) ==
          negative + ": pixels: texel (1, 1) is negative: emitted radiance is finite and >= 0");
    const std::string infinite = frame_source_write("infinite.exr", 1, 1, 3, {0, INFINITY, 0});
    CHECK(frame_source_error([&] { lab::ibl::read_frame(describe(infinite), 0); }) ==
          infinite + ": pixels: texel (0, 0) is not finite: emitted radiance is finite and >= 0");
    const std::string wide = frame_source_write("wide.exr", 16385, 1, 1, std::vector<float>(16385, 1.0f));
    CHECK(frame_source_error([&] { lab::ibl::read_frame(describe(wide), 0); }) == wide + ": size: 16385 x 1 is outside 1 to 16384 a side");
    // the sequence's missing frame names its file and its number
    const FrameSource sequence = describe((frame_source_scratch() / "gone_%03d.exr").string(), 24.0);
    CHECK(frame_source_error([&] { lab::ibl::read_frame(sequence, 7); }) ==
          (frame_source_scratch() / "gone_007.exr").string() + ": no such file (frame 7 of the sequence " + sequence.path + ")");
}
