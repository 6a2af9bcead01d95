// The heat-map chart (plots/heatmap_chart.hpp): a real PNG and its CSV, and bad input refused
// before any work.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/child_process.hpp"
#include "plots/heatmap_chart.hpp"
#include "plots/python_runner.hpp"
#include "tests/chart_files.hpp"

namespace fs = std::filesystem;
using lab::plots::HeatmapPanel;

TEST_CASE("the heat-map chart is a PNG, and its CSV has one row per panel and point", "[film][python]") {
    lab::TempFolder folder("test");
    const fs::path png = folder.path() / "heat.png", csv = folder.path() / "heat.csv";
    const std::vector<HeatmapPanel> panels = {{"loses", {0.5, 0.7, 0.9, 1.0, 1.0, 1.0}}, {"creates, a lot", {1.0, 1.2, 1.5, 2.0, 1.1, 1.0}}};
    lab::plots::write_heatmap_chart(panels, {0.1, 0.5, 1.0}, {0.0, 45.0}, "roughness", "theta", "albedo", 1.0, "t", png.string(), csv.string());
    CHECK(is_png_larger_than(png, 20000u));
    const std::vector<std::string> lines = lines_of(csv);
    REQUIRE(lines.size() == 13u);
    CHECK(lines[0] == "panel,x,y,value");
    CHECK(lines[2] == "loses,0.1,45,0.7");  // x-major: the second value is (x[0], y[1])
    CHECK(lines[12] == "\"creates, a lot\",1,45,1");
}

TEST_CASE("the heat-map chart refuses no panels, an empty axis, a panel of the wrong size and a value that is not finite", "[film]") {
    const std::string png = (fs::temp_directory_path() / "dtoadq_test_heat.png").string();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto chart = [&](const std::vector<HeatmapPanel>& panels, const std::vector<double>& x) {
        lab::plots::write_heatmap_chart(panels, x, {0.0}, "x", "y", "v", 1.0, "t", png, "");
    };
    CHECK_THROWS_AS(chart({}, {1.0}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {}}}, {}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {1.0}}}, {1.0, 2.0}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {nan}}}, {1.0}), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_heatmap_chart({{"a", {1.0, 2.0}}}, {0.0, 1.0}, {0.0}, "x", "y", "v", 1.0, "t", png, "", true),
                    std::invalid_argument);  // x = 0 on a logarithmic axis
    CHECK_FALSE(fs::exists(png));
}

TEST_CASE("the heat-map chart draws a logarithmic x axis, and a quantity on one side of its centre", "[film][python]") {
    lab::TempFolder folder("test");
    const fs::path png = folder.path() / "heat.png";
    // rays lost, 0 at best: nothing below the centre
    lab::plots::write_heatmap_chart({{"lost", {0.0, 50.0, 0.0, 10.0, 0.0, 0.0}}}, {0.3, 1.0, 3.0}, {1.0, 1.5}, "factor", "omega", "lost (%)", 0.0,
                                    "t", png.string(), "", true);
    CHECK(is_png_larger_than(png, 10000u));
}
