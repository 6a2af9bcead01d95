// The trade-off chart (plots/tradeoff_chart.hpp): a real PNG and its CSV, and bad input refused
// before any work.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/child_process.hpp"
#include "plots/python_runner.hpp"
#include "tests/chart_files.hpp"
#include "plots/tradeoff_chart.hpp"

namespace fs = std::filesystem;
using lab::plots::TradeoffPoint;

TEST_CASE("the trade-off chart is a PNG, and its CSV has one row per setting", "[film][python]") {
    lab::TempFolder folder("test");
    const fs::path png = folder.path() / "tradeoff.png", csv = folder.path() / "tradeoff.csv";
    const std::vector<TradeoffPoint> points = {{"ω 1, central", 0.016, 0.0}, {"ω 1.8, tetrahedral", 0.012, 0.003}};
    lab::plots::write_tradeoff_chart(points, 0.002, "metaballs", "relative error", png.string(), csv.string());
    CHECK(is_png_larger_than(png, 20000u));
    const std::vector<std::string> lines = lines_of(csv);
    CHECK(lines == std::vector<std::string>{"setting,seconds,error", "\"ω 1, central\",0.016,0", "\"ω 1.8, tetrahedral\",0.012,0.003"});
}

TEST_CASE("the trade-off chart refuses no points, a bad time or error, and a bad noise level", "[film]") {
    const std::string png = (fs::temp_directory_path() / "dtoadq_test_tradeoff.png").string();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(lab::plots::write_tradeoff_chart({}, 0.0, "t", "e", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_tradeoff_chart({{"a", 0.0, 0.1}}, 0.0, "t", "e", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_tradeoff_chart({{"a", 0.1, -0.1}}, 0.0, "t", "e", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_tradeoff_chart({{"a", 0.1, nan}}, 0.0, "t", "e", png, ""), std::invalid_argument);
    CHECK_THROWS_AS(lab::plots::write_tradeoff_chart({{"a", 0.1, 0.1}}, nan, "t", "e", png, ""), std::invalid_argument);
    CHECK_FALSE(fs::exists(png));
}
