// EXR and PNG files: exact round trips with metadata, output path checks before a render, and
// atomic writes: a failed write leaves the old file as it was and nothing else behind.
#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "film/atomic_file.hpp"
#include "film/image_output.hpp"
#include "plots/python_runner.hpp"

namespace fs = std::filesystem;
using lab::film::ImageRgb;
using lab::film::ToneMap;

namespace {

struct Scratch {
    lab::TempFolder folder{"test"};
    std::string operator/(const std::string& name) const { return (folder.path() / name).string(); }
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(folder.path())) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

ImageRgb noise(int w, int h, unsigned seed) {
    ImageRgb image(w, h);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    for (float& v : image.rgb) v = u(rng);
    return image;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

bool same_bits(const ImageRgb& a, const ImageRgb& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// Lowers this process's file size limit for its lifetime (root is bound by it too), with SIGXFSZ
// ignored so that a write past it fails with EFBIG instead of ending the process.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit lower = old_;
        lower.rlim_cur = bytes;
        ok_ = setrlimit(RLIMIT_FSIZE, &lower) == 0;
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, old_handler_);
    }
    bool ok() const { return ok_; }

private:
    rlimit old_{};
    void (*old_handler_)(int) = nullptr;
    bool ok_ = false;
};

}  // namespace

TEST_CASE("EXR round trip: every float exactly, NaN and infinity kept, metadata typed", "[film]") {
    Scratch scratch;
    ImageRgb image = noise(7, 5, 1);
    image.set(0, 0, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity());
    image.set(6, 4, -0.25f, 1e-40f /* denormal */, 65504.0f * 4.0f /* beyond half */);
    lab::film::ImageMetadata meta;
    meta.software = "dtoadq 0.1 (test)";
    meta.set("scene", "scenes/box, \"quoted\".json");
    meta.set("spp", 128);
    meta.set("seconds", 12.5);
    meta.set("exposure", -0.75f);
    lab::film::write_exr(scratch / "out.exr", image, meta);

    lab::film::ImageMetadata back;
    ImageRgb read = lab::film::read_image(scratch / "out.exr", &back);
    CHECK(same_bits(read, image));
    CHECK(back.software == "dtoadq 0.1 (test)");
    REQUIRE(back.values.size() == 4u);
    CHECK(std::get<std::string>(*back.find("scene")) == "scenes/box, \"quoted\".json");
    CHECK(std::get<int>(*back.find("spp")) == 128);
    CHECK(std::get<float>(*back.find("seconds")) == 12.5f);
    CHECK(std::get<float>(*back.find("exposure")) == -0.75f);
    CHECK(back.find("absent") == nullptr);
    CHECK(scratch.files() == std::vector<std::string>{"out.exr"});  // no temporary left
}

TEST_CASE("PNG round trip: the same 8-bit values, sRGB decoded - metadata as text", "[film]") {
    Scratch scratch;
    ImageRgb image = noise(9, 4, 2);
    for (float& v : image.rgb) v *= 0.25f;  // [0, 1]: Clamp is then the identity
    image.set(3, 2, std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
    lab::film::ImageMetadata meta;
    meta.set("spp", 64);
    meta.set("seconds", 1.5f);
    meta.set("tonemap", "clamp");
    lab::film::write_png(scratch / "out.png", image, ToneMap::Clamp, 0.0f, meta);

    lab::film::ImageMetadata back;
    ImageRgb read = lab::film::read_image(scratch / "out.png", &back);
    REQUIRE(read.width == 9);
    REQUIRE(read.height == 4);
    // encoding what was read gives the very bytes that were written
    const std::vector<uint8_t> written = lab::film::to_srgb8(image, ToneMap::Clamp, 0.0f);
    CHECK(lab::film::to_srgb8(read, ToneMap::Clamp, 0.0f) == written);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 9; ++x) {
            if (x == 3 && y == 2) continue;
            for (int c = 0; c < 3; ++c)  // within half an 8-bit step of the encoded value
                REQUIRE(std::fabs(lab::film::srgb_encode(read.at(x, y)[c]) - lab::film::srgb_encode(image.at(x, y)[c])) <= 0.5f / 255.0f + 1e-6f);
        }
    CHECK(read.at(3, 2) == std::array<float, 3>{1.0f, 0.0f, 1.0f});  // the NaN pixel: magenta
    CHECK(back.software == "dtoadq");
    CHECK(std::get<std::string>(*back.find("spp")) == "64");
    CHECK(std::get<std::string>(*back.find("seconds")) == "1.5");
    CHECK(std::get<std::string>(*back.find("tonemap")) == "clamp");
}

TEST_CASE("PNG from 8-bit sRGB bytes (the viewer's screenshot): the same bytes back, sizes checked", "[film]") {
    Scratch scratch;
    const std::vector<uint8_t> bytes = {0, 1, 2, 127, 128, 129, 253, 254, 255, 10, 200, 30};  // 2 x 2 pixels
    lab::film::write_srgb8_png(scratch / "shot.png", 2, 2, bytes, {});
    const ImageRgb read = lab::film::read_image(scratch / "shot.png");
    REQUIRE(read.width == 2);
    REQUIRE(read.height == 2);
    CHECK(lab::film::to_srgb8(read, ToneMap::Clamp, 0.0f) == bytes);
    CHECK_THROWS_AS(lab::film::write_srgb8_png(scratch / "short.png", 2, 2, std::vector<uint8_t>(11), {}), std::invalid_argument);
    CHECK(scratch.files() == std::vector<std::string>{"shot.png"});
}

TEST_CASE("write_image picks the format by the extension", "[film]") {
    Scratch scratch;
    ImageRgb image = noise(3, 3, 3);
    lab::film::write_image(scratch / "a.EXR", image, ToneMap::Aces, 0.0f, {});
    lab::film::write_image(scratch / "b.png", image, ToneMap::Aces, 0.0f, {});
    CHECK(same_bits(lab::film::read_image(scratch / "a.EXR"), image));
    std::ifstream png(scratch / "b.png", std::ios::binary);
    char magic[8] = {};
    png.read(magic, 8);
    CHECK(std::string(magic, 8) == "\x89PNG\r\n\x1a\n");
}

TEST_CASE("output paths are checked before rendering, with one line each", "[film]") {
    Scratch scratch;
    CHECK_NOTHROW(lab::film::check_output_path(scratch / "render.exr"));
    CHECK_NOTHROW(lab::film::check_output_path(scratch / "render.PNG"));
    const std::string jpg = scratch / "render.jpg";
    CHECK(error_of([&] { lab::film::check_output_path(jpg); }) ==
          jpg + ": unsupported image format \".jpg\": use .exr (linear float) or .png (8-bit sRGB)");
    const std::string bare = scratch / "render";
    CHECK(error_of([&] { lab::film::check_output_path(bare); }) == bare + ": no image extension: use .exr (linear float) or .png (8-bit sRGB)");
    CHECK(error_of([] { lab::film::check_output_path("/nonexistent-folder/render.exr"); }) ==
          "/nonexistent-folder/render.exr: cannot write: folder /nonexistent-folder does not exist");
    fs::create_directory(scratch / "taken.png");
    CHECK(error_of([&] { lab::film::check_output_path(scratch / "taken.png"); }) == scratch / "taken.png" + ": is a folder, not a file");
    CHECK(error_of([] { lab::film::check_output_path(""); }) == "command line: the output image path is empty");
    CHECK(scratch.files() == std::vector<std::string>{"taken.png"});  // checking wrote nothing
}

TEST_CASE("reading a missing, foreign or broken file names it", "[film]") {
    Scratch scratch;
    CHECK(error_of([&] { lab::film::read_image(scratch / "none.exr"); }) == scratch / "none.exr" + ": cannot read: no such file");
    {
        std::ofstream broken(scratch / "broken.exr", std::ios::binary);
        broken << "not an image";
    }
    CHECK(error_of([&] { lab::film::read_image(scratch / "broken.exr"); }).rfind(scratch / "broken.exr: cannot read: ", 0) == 0);
}

TEST_CASE("a failed write leaves the existing file as it was and no partial file", "[film]") {
    Scratch scratch;
    const std::string path = scratch / "out.exr";
    const ImageRgb old_image = noise(4, 4, 4);
    lab::film::write_exr(path, old_image, {});
    const auto old_size = fs::file_size(path);

    SECTION("the disk refuses the data (file size limit, which binds root too)") {
        const ImageRgb big = noise(128, 128, 5);  // some 190 kB of incompressible floats
        std::string error;
        {
            FileSizeLimit limit(4096);
            REQUIRE(limit.ok());
            error = error_of([&] { lab::film::write_exr(path, big, {}); });
        }
        CHECK(error == path + ": cannot write: File too large");
        CHECK(error_of([&] { lab::film::write_png(scratch / "out.png", big, ToneMap::Aces, 0.0f, {}); }) == "(no error)");  // limit lifted
        fs::remove(scratch / "out.png");
    }
    SECTION("the folder is gone between the check and the write") {
        const std::string inner = scratch / "inner";
        fs::create_directory(inner);
        lab::film::check_output_path(inner + "/out.exr");
        fs::remove(inner);
        CHECK(error_of([&] { lab::film::write_exr(inner + "/out.exr", old_image, {}); }) ==
              inner + "/out.exr: cannot write: folder " + inner + " does not exist");
        // and below the checks, at the open itself
        CHECK(error_of([&] { lab::film::write_file_atomically(inner + "/out.exr", "x", 1); }) ==
              inner + "/out.exr: cannot write: No such file or directory");
    }
    SECTION("a folder is in the way of the rename") {
        fs::create_directory(scratch / "folder.exr");
        { std::ofstream(scratch / "folder.exr/keep.txt") << "kept"; }
        CHECK(error_of([&] { lab::film::write_file_atomically(scratch / "folder.exr", "data", 4); }) ==
              scratch / "folder.exr" + ": cannot write: Is a directory");
        CHECK(fs::is_regular_file(scratch / "folder.exr/keep.txt"));
        fs::remove_all(scratch / "folder.exr");
    }
    CHECK(fs::file_size(path) == old_size);
    CHECK(same_bits(lab::film::read_image(path), old_image));
    CHECK(scratch.files() == std::vector<std::string>{"out.exr"});
}

TEST_CASE("an atomic write keeps the mode of the file it replaces", "[film]") {
    Scratch scratch;
    const std::string path = scratch / "mode.png";
    lab::film::write_file_atomically(path, "one", 3);
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    lab::film::write_file_atomically(path, "second", 6);
    CHECK(fs::file_size(path) == 6u);
    CHECK(fs::status(path).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}
