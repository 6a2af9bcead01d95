// Preset files: every bundled preset loads, round-trips, and bad input names the file and field.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"

namespace fs = std::filesystem;

namespace {

std::string error_of(const std::string& json_text) {
    try {
        brdf::parse_preset(nlohmann::json::parse(json_text), "mine.json");
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("every bundled preset loads and round-trips through JSON", "[presets]") {
    int count = 0;
    for (const auto& entry : fs::directory_iterator("presets")) {
        if (entry.path().extension() != ".json") continue;
        ++count;
        INFO(entry.path());
        brdf::Preset p = brdf::load_preset(entry.path().string());
        brdf::Preset again = brdf::parse_preset(brdf::preset_to_json(p), "roundtrip");
        CHECK(again.name == p.name);
        CHECK(again.material.model == p.material.model);
        CHECK(again.material.distribution == p.material.distribution);
        for (const brdf::ScalarParameter& param : brdf::scalar_parameters())
            if (param.field) CHECK(again.material.*param.field == Approx(p.material.*param.field).margin(1e-6));
        for (int c = 0; c < 3; ++c) CHECK(again.material.albedo[c] == Approx(p.material.albedo[c]));
    }
    // the lab ships at least these: conductors, dielectrics, a matte clay, skin, glass and the 2017 model
    for (const char* name : {"gold", "copper", "brushed_aluminium", "glossy_plastic", "rubber", "clay", "skin", "glass", "dtoadq2017_typical"})
        CHECK(fs::exists(fs::path("presets") / (std::string(name) + ".json")));
    CHECK(count >= 8);
}

TEST_CASE("bad presets give one line naming the file and the field", "[presets]") {
    CHECK(error_of(R"({"roughnes": 0.5})") == "mine.json: roughnes: unknown key");
    CHECK(error_of(R"({"lobes": {"glosy": 1}})") == "mine.json: lobes.glosy: unknown key");
    CHECK(error_of(R"({"roughness": "rough"})") == "mine.json: roughness: expected a number, got string");
    CHECK(error_of(R"({"roughness": 1.5})") == "mine.json: roughness: value 1.5 is out of range [0, 1]");
    CHECK(error_of(R"({"hc_shape": 1.2})") == "mine.json: hc_shape: value 1.2 is out of range [1.6, 16]");
    CHECK(error_of(R"({"albedo": [1, 0.5]})") == "mine.json: albedo: expected an array of 3 numbers (linear RGB)");
    CHECK(error_of(R"({"albedo": [1, -0.5, 0]})") == "mine.json: albedo[1]: value -0.5 is out of range [0, 1]");
    CHECK(error_of(R"({"model": "disney"})") == "mine.json: model: unknown value \"disney\" (expected \"lab\" or \"dtoadq2017\")");
    CHECK(error_of(R"({"lobes": 3})") == "mine.json: lobes: expected an object, got number");
    CHECK(error_of(R"([1, 2])") == "mine.json: a preset must be a JSON object");
    CHECK(error_of(R"({"roughness": 0.5})").empty());
}

TEST_CASE("an unreadable or malformed preset file is one clear line", "[presets]") {
    try {
        brdf::load_preset("presets/does_not_exist.json");
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "presets/does_not_exist.json: cannot open preset file");
    }
    fs::path bad = fs::temp_directory_path() / "dtoadq_bad_preset.json";
    std::ofstream(bad) << "{\"roughness\": 0.5,,}";
    try {
        brdf::load_preset(bad.string());
        FAIL("no error");
    } catch (const lab::InputError& e) {
        std::string what = e.what();
        CHECK(what.find(bad.string() + ": roughness: malformed JSON: ") == 0);
        CHECK(what.find('\n') == std::string::npos);
    }
    std::ofstream(bad) << "{\"ior\": 1e999}";  // overflows: JSON has no infinity
    try {
        brdf::load_preset(bad.string());
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()).find(bad.string() + ": ior: malformed JSON: number overflow") == 0);
    }
    fs::remove(bad);
}

TEST_CASE("docs/materials.md lists every parameter with its range and default", "[presets][docs]") {
    std::ifstream in("docs/materials.md");
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    for (const brdf::ScalarParameter& p : brdf::scalar_parameters()) {
        std::ostringstream row;
        row << "| `" << p.key << "` | " << p.min << " | " << p.max << " | " << p.fallback << " |";
        INFO(row.str());
        CHECK(text.str().find(row.str()) != std::string::npos);
    }
}
