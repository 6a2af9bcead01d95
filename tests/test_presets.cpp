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
        for (const brdf::ScalarParameter& param : brdf::parameters_of_model(p.material.model))
            if (param.field) CHECK(again.material.*param.field == Approx(p.material.*param.field).margin(1e-6));
            else if (param.color)
                for (int c = 0; c < 3; ++c) CHECK((again.material.*param.color)[c] == Approx((p.material.*param.color)[c]));
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
    CHECK(error_of(R"({"model": "disney"})") == "mine.json: model: unknown value \"disney\" (expected \"lab\", \"dtoadq2017\" or \"openpbr\")");
    CHECK(error_of(R"({"lobes": 3})") == "mine.json: lobes: expected an object, got number");
    CHECK(error_of(R"([1, 2])") == "mine.json: a preset must be a JSON object");
    CHECK(error_of(R"({"roughness": 0.5})").empty());
}

TEST_CASE("openpbr presets: OpenPBR's input names as flat keys, each left out at OpenPBR's default", "[presets][openpbr]") {
    brdf::Preset p = brdf::parse_preset(nlohmann::json::parse(R"({"model": "openpbr", "base_color": [0.8, 0.1, 0.1], "coat_weight": 1,
                                                                  "thin_film_thickness": 0.5, "subsurface_scatter_anisotropy": -0.4})"),
                                        "mine.json");
    CHECK(p.material.model == BRDF_MODEL_OPENPBR);
    CHECK(p.material.albedo[1] == 0.1f);
    CHECK(p.material.coat_weight == 1.0f);
    CHECK(p.material.subsurface_asymmetry == -0.4f);
    // the rest at open_pbr_surface.mtlx's defaults, shared fields included
    CHECK(p.material.roughness == 0.3f);
    CHECK(p.material.coat_ior == 1.6f);
    CHECK(p.material.coat_darkening == 1.0f);
    CHECK(p.material.fuzz_roughness == 0.5f);
    CHECK(p.material.thin_film_ior == 1.4f);
    CHECK(p.material.subsurface_color[0] == 0.8f);
    CHECK(p.material.specular_color[2] == 1.0f);
    CHECK(p.material.metallic == 0.0f);
    CHECK(p.material.ior == 1.5f);
    brdf::Material defaults = brdf::default_material(BRDF_MODEL_OPENPBR);
    for (const brdf::ScalarParameter& param : brdf::openpbr_parameters()) {
        INFO(param.key);
        if (param.field) CHECK(defaults.*param.field == param.fallback);
        else
            for (float c : defaults.*param.color) CHECK(c == param.fallback);
        CHECK(std::string(param.group).size() > 0);
    }
    // a lab material keeps the lab's defaults where the two share a field
    CHECK(brdf::default_material().roughness == 0.5f);
    CHECK(brdf::default_material().subsurface_asymmetry == -0.3f);
}

TEST_CASE("bad openpbr presets give one line naming the file and the field", "[presets][openpbr]") {
    CHECK(error_of(R"({"model": "openpbr", "roughness": 0.5})") ==
          "mine.json: roughness: unknown key for model \"openpbr\" (its keys are OpenPBR Surface's inputs)");
    CHECK(error_of(R"({"model": "openpbr", "coat_weight": 1.5})") == "mine.json: coat_weight: value 1.5 is out of range [0, 1]");
    CHECK(error_of(R"({"model": "openpbr", "coat_ior": 0.5})") == "mine.json: coat_ior: value 0.5 is out of range [1, 3]");
    CHECK(error_of(R"({"model": "openpbr", "fuzz_color": [1, 1]})") == "mine.json: fuzz_color: expected an array of 3 numbers (linear RGB)");
    CHECK(error_of(R"({"model": "openpbr", "coat_color": [1, 2, 0]})") == "mine.json: coat_color[1]: value 2 is out of range [0, 1]");
    CHECK(error_of(R"({"model": "openpbr", "thin_film_thickness": "thin"})") == "mine.json: thin_film_thickness: expected a number, got string");
    CHECK(error_of(R"({"model": "openpbr", "distribution": "ggx"})") ==
          "mine.json: distribution: unknown key for model \"openpbr\" (its keys are OpenPBR Surface's inputs)");
    CHECK(error_of(R"({"model": 3})") == "mine.json: model: expected a string, got number");
    try {
        brdf::parse_preset_text(R"({"model": "openpbr", "fuzz_weight": 1e999})", "mine.json");
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()).rfind("mine.json: fuzz_weight: malformed JSON", 0) == 0);
    }
    CHECK(error_of(R"({"model": "openpbr", "fuzz_weight": 0.5})").empty());
    // emission, in nits: from the same table
    CHECK(error_of(R"({"model": "openpbr", "emission_luminance": -1})") == "mine.json: emission_luminance: value -1 is out of range [0, 1e+06]");
    CHECK(error_of(R"({"model": "openpbr", "emission_luminance": 2e6})") == "mine.json: emission_luminance: value 2e+06 is out of range [0, 1e+06]");
    CHECK(error_of(R"({"model": "openpbr", "emission_color": [1, 1, -0.5]})") == "mine.json: emission_color[2]: value -0.5 is out of range [0, 1]");
    CHECK(error_of(R"({"model": "openpbr", "emission_luminance": 1000, "emission_color": [1, 0.5, 0]})").empty());
    CHECK(error_of(R"({"emission_luminance": 10})") == "mine.json: emission_luminance: unknown key");  // an OpenPBR input, not the lab model's
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
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        std::ostringstream row;
        row << "| `" << p.key << "` | " << p.min << " | " << p.max << " | " << p.fallback << " | " << p.unit << " | " << p.group << " |";
        INFO(row.str());
        CHECK(text.str().find(row.str()) != std::string::npos);
    }
}
