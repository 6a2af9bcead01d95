// Frame patterns (common/frame_pattern.hpp): one %d or %0Nd filled with the frame number, %% a
// percent sign, and every other pattern refused with one line that says what it holds.
#include <catch2/catch.hpp>

#include <string>

#include "common/frame_pattern.hpp"
#include "common/input_error.hpp"

namespace {

std::string pattern_error(const std::string& pattern) {
    try {
        lab::check_frame_pattern(pattern, "the output");
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("frame patterns: the number zero-padded to the width, %% a percent sign", "[film]") {
    CHECK(lab::frame_path("out_%04d.exr", 7) == "out_0007.exr");
    CHECK(lab::frame_path("out_%04d.exr", 12345) == "out_12345.exr");
    CHECK(lab::frame_path("f_%d.png", 0) == "f_0.png");
    CHECK(lab::frame_path("f_%d.png", 240) == "f_240.png");
    CHECK(lab::frame_path("100%%/%03d.exr", 5) == "100%/005.exr");
    CHECK(lab::frame_path("d%02d_%%d.exr", 3) == "d03_%d.exr");
    for (const char* good : {"a_%d.exr", "a_%010d.exr", "%d", "x%%_%3d"}) {
        INFO(good);
        CHECK(lab::is_frame_pattern(good) == (std::string(good) != "x%%_%3d"));
    }
    for (const char* bad : {"a.exr", "%d_%d.exr", "%s_%d.exr", "%5d.exr", "%%d.exr", "a_%", "a_%0"}) {
        INFO(bad);
        CHECK_FALSE(lab::is_frame_pattern(bad));
    }
}

TEST_CASE("frame patterns: a pattern without one conversion is one line naming it", "[film]") {
    CHECK(pattern_error("s_%04d.exr") == "(no error)");
    CHECK(pattern_error("s.exr") ==
          "s.exr: the output needs one %d or %0Nd for the frame number (frame_%04d.exr), and this has no %d");
    CHECK(pattern_error("s_%d_%04d.exr") ==
          "s_%d_%04d.exr: the output needs one %d or %0Nd for the frame number (frame_%04d.exr), and this has 2 of them");
    CHECK(pattern_error("s_%x.exr") ==
          "s_%x.exr: the output needs one %d or %0Nd for the frame number (frame_%04d.exr), and this has a % that is not %d, %0Nd or %%");
}
