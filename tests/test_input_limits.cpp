// The loaders' limits (scene/scene_limits.hpp, the preset's): a file far beyond any real one stops
// with one line naming the file and what was too much - a 50,000-level nested scene would overflow
// the parser's stack - and a scene just inside the limits still loads.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_limits.hpp"

namespace {

const char* const kCamera = R"("camera": {"type": "pinhole", "position": [0, 1, 4], "look_at": [0, 0, 0]},)"
                            R"("materials": {"m": {"albedo": [0.5, 0.5, 0.5]}},)";

// A sphere inside `depth` translate nodes: {"type": "translate", "offset": [0,0,0], "child": ...}.
std::string nested_scene(int depth) {
    std::string shape;
    shape.reserve(size_t(depth) * 60 + 64);
    for (int i = 0; i < depth; ++i) shape += R"({"type": "translate", "offset": [0, 0, 0], "child": )";
    shape += R"({"type": "sphere", "radius": 1})";
    shape.append(size_t(depth), '}');
    return std::string("{") + kCamera + R"("objects": [{"name": "deep", "material": "m", "shape": )" + shape + "}]}";
}

// One union of `count` spheres.
std::string wide_scene(int count) {
    std::string children;
    for (int i = 0; i < count; ++i) children += std::string(i ? "," : "") + R"({"type": "sphere", "radius": 1})";
    return std::string("{") + kCamera + R"("objects": [{"name": "wide", "material": "m", "shape": {"type": "union", "children": [)" +
           children + "]}}]}";
}

std::string error_of(const std::string& scene_text) {
    try {
        lab::scene::parse_scene(scene_text, "deep.json");
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string scratch(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

}  // namespace

TEST_CASE("a shape tree nested 50,000 levels deep is one clear error, not a stack overflow", "[scene][limits]") {
    const std::string text = nested_scene(50000);
    CHECK(text.size() > 1500000);  // as large as the 1.7 MB file that overflowed an unlimited parser
    const std::string error = error_of(text);
    INFO(error.substr(0, 300));
    CHECK(error.rfind("deep.json: objects[0].shape.child.child.", 0) == 0);
    CHECK(error.find(": nested more than 400 objects and arrays deep (the limit of a scene file)") != std::string::npos);
    // a deep but reasonable tree (100 transforms) loads
    CHECK(lab::scene::parse_scene(nested_scene(100), "deep.json").objects.size() == 1);
}

TEST_CASE("a scene with more shape nodes than a kernel should hold is refused", "[scene][limits]") {
    CHECK(error_of(wide_scene(int(lab::scene::kMaxShapeNodes))) ==
          "deep.json: objects: 20001 shape nodes, more than the 20000 a scene may hold");
    CHECK(lab::scene::parse_scene(wide_scene(1000), "deep.json").objects.size() == 1);
}

TEST_CASE("scene and preset files far larger than any real one are refused before they are read", "[scene][limits]") {
    const std::string scene = scratch("dtoadq_limits_huge_scene.json");
    {
        std::ofstream out(scene, std::ios::binary);
        out << std::string(lab::scene::kMaxSceneFileBytes + 1, ' ');
    }
    try {
        lab::scene::load_scene(scene);
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == scene + ": is 16777217 bytes, more than the 16777216 a scene file may hold");
    }
    std::filesystem::remove(scene);

    const std::string preset = scratch("dtoadq_limits_huge_preset.json");
    {
        std::ofstream out(preset, std::ios::binary);
        out << "{\"name\": \"" << std::string(1u << 20, 'x') << "\"}";
    }
    try {
        brdf::load_preset(preset);
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == preset + ": is 1048588 bytes, more than the 1048576 a preset file may hold");
    }
    std::filesystem::remove(preset);
}

TEST_CASE("a preset nested absurdly deep is one error naming the field", "[presets][limits]") {
    std::string text = R"({"roughness": )" + std::string(50000, '[') + std::string(50000, ']') + "}";
    try {
        brdf::parse_preset_text(text, "deep_preset.json");
        FAIL("no error");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "deep_preset.json: roughness: nested more than 32 levels deep");
    }
}
