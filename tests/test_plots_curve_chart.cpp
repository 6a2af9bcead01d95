// The curve chart (plots/curve_chart.hpp): a real PNG and its CSV, and bad input refused before any
// work.
#include <catch2/catch.hpp>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/child_process.hpp"
#include "plots/curve_chart.hpp"
#include "plots/python_runner.hpp"
#include "tests/chart_files.hpp"

namespace fs = std::filesystem;
using lab::plots::Curve;

TEST_CASE("the curve chart is a PNG, and its CSV has one row per curve and point", "[film][python]") {
    lab::TempFolder folder("test");
    const fs::path png = folder.path() / "curves.png", csv = folder.path() / "curves.csv";
    const std::vector<Curve> curves = {{"largest, error", {1.0, 10.0, 100.0}, {3e-4, 3e-4, 2e-3}, false},
                                       {"threshold", {1.0, 100.0}, {2e-4, 2e-4}, true}};
    lab::plots::write_curve_chart(curves, "distance", "error", "t", png.string(), csv.string());
    CHECK(is_png_larger_than(png, 20000u));
    const std::vector<std::string> lines = lines_of(csv);
    CHECK(lines == std::vector<std::string>{"curve,kind,x,y", "\"largest, error\",measured,1,0.0003", "\"largest, error\",measured,10,0.0003",
                                            "\"largest, error\",measured,100,0.002", "threshold,reference,1,0.0002", "threshold,reference,100,0.0002"});
}

TEST_CASE("the curve chart refuses no curves, an empty or uneven curve, a value a log axis cannot show, and a name given twice", "[film]") {
    const std::string png = (fs::temp_directory_path() / "dtoadq_test_curves.png").string();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto chart = [&](const std::vector<Curve>& curves) { lab::plots::write_curve_chart(curves, "x", "y", "t", png, ""); };
    CHECK_THROWS_AS(chart({}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {}, {}, false}}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {1.0, 2.0}, {1.0}, false}}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {1.0}, {0.0}, false}}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {-1.0}, {1.0}, false}}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {1.0}, {nan}, false}}), std::invalid_argument);
    CHECK_THROWS_AS(chart({{"a", {1.0}, {1.0}, false}, {"a", {2.0}, {1.0}, true}}), std::invalid_argument);
    CHECK_FALSE(fs::exists(png));
}
