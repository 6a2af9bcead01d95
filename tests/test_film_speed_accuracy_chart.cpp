// The speed-accuracy chart: a real PNG and its CSV, and bad input refused before any work.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "plots/python_runner.hpp"
#include "plots/speed_accuracy_chart.hpp"

namespace fs = std::filesystem;
using lab::plots::ConvergenceSeries;

namespace {

std::vector<std::string> lines_of(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<ConvergenceSeries> two_strategies() {
    ConvergenceSeries cosine{"bsdf, cosine", {0.5, 1.0, 2.0, 4.0}, {0.1, 0.0707, 0.05, 0.0354}};
    ConvergenceSeries mis{"mis", {0.6, 1.2, 2.4}, {0.04, 0.0283, 0.02}};
    return {cosine, mis};
}

}  // namespace

TEST_CASE("the speed-accuracy chart is a PNG, and its CSV has one row per point", "[film][python]") {
    lab::TempFolder folder("test");
    const fs::path png = folder.path() / "speed.png", csv = folder.path() / "speed.csv";
    lab::plots::write_speed_accuracy_chart(two_strategies(), "-- box scene, 256x256", png.string(), csv.string());
    std::ifstream in(png, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    CHECK(std::string(magic, 8) == "\x89PNG\r\n\x1a\n");
    CHECK(fs::file_size(png) > 20000u);
    const std::vector<std::string> expected = {"series,seconds,rmse", "\"bsdf, cosine\",0.5,0.1", "\"bsdf, cosine\",1,0.0707",
                                               "\"bsdf, cosine\",2,0.05",  "\"bsdf, cosine\",4,0.0354", "mis,0.6,0.04",
                                               "mis,1.2,0.0283",           "mis,2.4,0.02"};
    CHECK(lines_of(csv) == expected);
    // without a CSV, a single point
    lab::plots::write_speed_accuracy_chart({{"one", {1.0}, {0.5}}}, "", (folder.path() / "one.png").string(), "");
    CHECK(fs::file_size(folder.path() / "one.png") > 10000u);
}

TEST_CASE("the speed-accuracy chart refuses bad paths and points it cannot draw", "[film]") {
    try {
        lab::plots::write_speed_accuracy_chart(two_strategies(), "t", "/nonexistent-folder/speed.png", "");
        FAIL("no error for an unwritable path");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "/nonexistent-folder/speed.png: cannot write: folder /nonexistent-folder does not exist");
    }
    lab::TempFolder folder("test");
    const std::string png = (folder.path() / "x.png").string();
    CHECK_THROWS_AS(lab::plots::write_speed_accuracy_chart({}, "t", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_speed_accuracy_chart({{"a", {1.0, 2.0}, {0.1}}}, "t", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_speed_accuracy_chart({{"a", {1.0, 2.0}, {0.1, 0.0}}}, "t", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_speed_accuracy_chart({{"a", {}, {}}}, "t", png, ""), std::invalid_argument);
    CHECK_FALSE(fs::exists(png));
}
