// The scene file parser (docs/scenes.md): every kind of bad input is one lab::InputError whose text
// names the scene file and the JSON path of the field, exactly; presets inline and from files;
// relative paths against the scene file's folder; what a valid file turns into.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "scene/json_fields.hpp"
#include "scene/load_scene.hpp"
#include "scene/parse_node.hpp"

using lab::scene::Json;
using lab::scene::Scene;

namespace {

// A valid scene, mutated by each case. Its preset path resolves from "scenes/" to presets/.
Json base_scene() {
    return Json::parse(R"({
      "camera": {"type": "pinhole", "position": [0, 1, 4], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov_degrees": 40},
      "materials": {
        "sample": "../presets/glossy_plastic.json",
        "gold": {"albedo": [1, 0.71, 0.29], "metallic": 1, "roughness": 0.3, "lobes": {"diffuse": 0, "glossy": 1}}
      },
      "objects": [
        {"name": "a", "material": "sample", "shape": {"type": "sphere", "radius": 1}},
        {"name": "b", "material": "gold",
         "shape": {"type": "translate", "offset": [2, 0, 0], "child": {"type": "box", "half_size": [0.5, 0.5, 0.5]}}},
        {"name": "c", "material": "sample",
         "shape": {"type": "union", "children": [{"type": "sphere", "radius": 0.5},
                                                 {"type": "torus", "major_radius": 1, "minor_radius": 0.2}]}}
      ],
      "emitters": [{"center": [0, 3, 0], "radius": 0.2, "radiance": [10, 10, 10]}]
    })");
}

const char* const kFile = "scenes/x.json";

std::string error_of_text(const std::string& text) {
    try {
        lab::scene::parse_scene(text, kFile);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string error_with(const std::string& pointer, const Json& value) {
    Json doc = base_scene();
    doc[Json::json_pointer(pointer)] = value;
    return error_of_text(doc.dump());
}

std::string error_without(const std::string& parent, const std::string& key) {
    Json doc = base_scene();
    doc[Json::json_pointer(parent)].erase(key);
    return error_of_text(doc.dump());
}

std::string error_loading(const std::string& path) {
    try {
        lab::scene::load_scene(path);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("scene parser: the base scene is valid", "[scene]") {
    Scene s = lab::scene::parse_scene(base_scene().dump(), kFile);
    CHECK(s.objects.size() == 3);
    CHECK(s.materials.size() == 3);  // sample, gold, the emitter's slot
}

TEST_CASE("scene parser: bad values name the file and the field's JSON path", "[scene]") {
    // {JSON pointer, the value set there (JSON text), the error}: plain strings, not Json values, since
    // a table of thousands of Json temporaries takes 35 s of CPU to compile under the sanitizers.
    struct Mutation {
        const char* pointer;
        const char* value;
        const char* expected;
    };
    const Mutation cases[] = {
        {"/objects/2/shape/children/0/radius", "-1",
         "scenes/x.json: objects[2].shape.children[0].radius: value -1 must be > 0"},
        {"/objects/2/shape/children/0/radius", "0",
         "scenes/x.json: objects[2].shape.children[0].radius: value 0 must be > 0"},
        {"/objects/2/shape/children/0/radius", R"("1")",
         "scenes/x.json: objects[2].shape.children[0].radius: expected a number, got string"},
        {"/objects/0/shape/radius", "1e39",
         "scenes/x.json: objects[0].shape.radius: value 1e+39 overflows a 32-bit float"},
        {"/objects/0/shape/colour", "1",
         "scenes/x.json: objects[0].shape.colour: unknown key (expected one of: type, radius)"},
        {"/objects/0/shape", R"({"radius": 1})",
         "scenes/x.json: objects[0].shape.type: missing required key"},
        {"/objects/0/shape", "1",
         "scenes/x.json: objects[0].shape: expected a node object, got number"},
        {"/objects/1/shape/offset", "[1, 2]",
         "scenes/x.json: objects[1].shape.offset: expected an array of 3 numbers"},
        {"/objects/1/shape/child/half_size/2", "-0.5",
         "scenes/x.json: objects[1].shape.child.half_size[2]: value -0.5 must be > 0"},
        {"/objects/2/shape/children", R"([{"type": "sphere", "radius": 1}])",
         "scenes/x.json: objects[2].shape.children: a combinator needs at least 2 children, got 1"},
        {"/objects/0/shape", R"({"type": "round_box", "half_size": [0.5, 0.2, 0.5], "radius": 0.3})",
         "scenes/x.json: objects[0].shape.radius: value 0.3 must be <= the smallest half_size 0.2"},
        {"/objects/0/shape", R"({"type": "repeat_limited", "period": [1, 1, 1], "count_min": [0, 0, 2],
                                              "count_max": [1, 0, 1], "child": {"type": "sphere", "radius": 0.1}})",
         "scenes/x.json: objects[0].shape.count_max[2]: value 1 must be >= count_min 2"},
        {"/objects/0/shape", R"({"type": "repeat_limited", "period": [1, 1, 1], "count_min": [0.5, 0, 0],
                                              "count_max": [1, 0, 1], "child": {"type": "sphere", "radius": 0.1}})",
         "scenes/x.json: objects[0].shape.count_min[0]: expected an integer, got 0.5"},
        {"/objects/0/shape", R"({"type": "repeat", "period": [0, 0, 0], "child": {"type": "sphere", "radius": 0.1}})",
         "scenes/x.json: objects[0].shape.period: must not be the zero vector"},
        {"/objects/0/shape", R"({"type": "rotate", "axis": [0, 1, 0], "degrees": 10, "euler_degrees": [0, 0, 0],
                                              "child": {"type": "sphere", "radius": 1}})",
         "scenes/x.json: objects[0].shape.euler_degrees: give either \"axis\" and \"degrees\" or \"euler_degrees\", not both"},
        {"/objects/0/shape", R"({"type": "rotate", "child": {"type": "sphere", "radius": 1}})",
         "scenes/x.json: objects[0].shape: a rotation needs \"axis\" and \"degrees\", or \"euler_degrees\""},
        {"/objects/0/shape", R"({"type": "rotate", "axis": [0, 0, 0], "degrees": 10, "child": {"type": "sphere", "radius": 1}})",
         "scenes/x.json: objects[0].shape.axis: must not be the zero vector"},
        {"/objects/0/shape", R"({"type": "plane", "normal": [0, 0, 0]})",
         "scenes/x.json: objects[0].shape.normal: must not be the zero vector"},
        {"/objects/0/shape", R"({"type": "displace", "amplitude": 0.1, "frequency": -2, "child": {"type": "sphere", "radius": 1}})",
         "scenes/x.json: objects[0].shape.frequency: value -2 must be > 0"},
        {"/objects/0/shape", R"({"type": "smooth_union", "children": [{"type": "sphere", "radius": 1}, {"type": "sphere", "radius": 2}]})",
         "scenes/x.json: objects[0].shape.radius: missing required key"},
        {"/objects/0/shape", R"({"type": "scale", "factor": 2, "child": {"type": "cone", "radius": 1, "height": -1}})",
         "scenes/x.json: objects[0].shape.child.height: value -1 must be > 0"},
        {"/camera/fov_degrees", "180",
         "scenes/x.json: camera.fov_degrees: value 180 is out of range (0, 180)"},
        {"/camera/fov_degrees", "0",
         "scenes/x.json: camera.fov_degrees: value 0 is out of range (0, 180)"},
        {"/camera/up", "[0, 0, 0]",
         "scenes/x.json: camera.up: must not be the zero vector"},
        {"/camera/up", "[0, 0, -2]",
         "scenes/x.json: camera.up: is parallel to the view direction (look_at - position)"},
        {"/camera/look_at", "[0, 1, 4]",
         "scenes/x.json: camera.look_at: equals camera.position: there is no view direction"},
        {"/camera/type", R"("fisheye")",
         "scenes/x.json: camera.type: unknown camera type \"fisheye\" (expected one of: pinhole, thin_lens)"},
        {"/camera/aperture_radius", "0.1",
         "scenes/x.json: camera.aperture_radius: unknown key (expected one of: type, position, look_at, up, fov_degrees, keyframes)"},
        {"/camera/type", R"("thin_lens")",
         "scenes/x.json: camera.aperture_radius: missing required key"},
        {"/objects/1/material", R"("silver")",
         "scenes/x.json: objects[1].material: material \"silver\" is not declared in \"materials\""},
        {"/objects/1/name", R"("a")",
         "scenes/x.json: objects[1].name: duplicate object name \"a\" (also objects[0])"},
        {"/objects/1/name", R"("")",
         "scenes/x.json: objects[1].name: an object name must not be empty"},
        {"/materials/sample", R"("../presets/nope.json")",
         "scenes/x.json: materials.sample: preset file \"../presets/nope.json\" not found (looked for presets/nope.json)"},
        {"/materials/gold/roughness", "1.5",
         "scenes/x.json: materials.gold.roughness: value 1.5 is out of range [0, 1]"},
        {"/materials/gold/lobes/glosy", "1",
         "scenes/x.json: materials.gold.lobes.glosy: unknown key"},
        {"/materials/gold/albedo", "[1, 2, 0]",
         "scenes/x.json: materials.gold.albedo[1]: value 2 is out of range [0, 1]"},
        {"/materials/gold", "3",
         "scenes/x.json: materials.gold: expected a preset file path (string) or an inline preset (object), got number"},
        {"/emitters/0/radiance/1", "-1",
         "scenes/x.json: emitters[0].radiance[1]: value -1 must be >= 0"},
        {"/emitters/0/radius", "-0.25",
         "scenes/x.json: emitters[0].radius: value -0.25 must be > 0"},
        {"/emitters/0/center", "[0, 1]",
         "scenes/x.json: emitters[0].center: expected an array of 3 numbers"},
        {"/emitters/0/type", R"("spot")",
         "scenes/x.json: emitters[0].type: unknown emitter type \"spot\" (expected one of: sphere, rect, disk, point)"},
        {"/emitters/0/type", "1",
         "scenes/x.json: emitters[0].type: expected a string, got number"},
        {"/emitters/0/material", R"("silver")",
         "scenes/x.json: emitters[0].material: material \"silver\" is not declared in \"materials\""},
        {"/emitters/0/material", "2",
         "scenes/x.json: emitters[0].material: expected a string, got number"},
        {"/emitters/0/intensity", "[1, 1, 1]",
         "scenes/x.json: emitters[0].intensity: unknown key (expected one of: type, center, radius, radiance, material)"},
        {"/emitters/1", R"({"type": "point", "position": [0, 1, 0], "intensity": [1, -2, 1]})",
         "scenes/x.json: emitters[1].intensity[1]: value -2 must be >= 0"},
        {"/emitters/1", R"({"type": "point", "position": [0, 1, 0]})",
         "scenes/x.json: emitters[1].intensity: missing required key"},
        {"/emitters/1", R"({"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1], "radius": 1})",
         "scenes/x.json: emitters[1].radius: unknown key (expected one of: type, position, intensity)"},
        {"/emitters/1", R"({"type": "point", "position": [0, "a", 0], "intensity": [1, 1, 1]})",
         "scenes/x.json: emitters[1].position[1]: expected a number, got string"},
        {"/emitters/1", "3",
         "scenes/x.json: emitters[1]: expected an object, got number"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [2, 0, 0], "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].edge_v: parallel to edge_u: the rect has no area"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [0, 0, 0], "edge_v": [0, 0, 1], "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].edge_u: must not be the zero vector"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "radiance": [1, -1, 1]})",
         "scenes/x.json: emitters[1].radiance[1]: value -1 must be >= 0"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 1e39], "edge_v": [0, 0, 1], "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].edge_u[2]: value 1e+39 overflows a 32-bit float"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].edge_v: missing required key"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "radius": 1, "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].radius: unknown key (expected one of: type, center, edge_u, edge_v, radiance, image, fps, material)"},
        {"/emitters/0/image", R"("screen.exr")",
         "scenes/x.json: emitters[0].image: only rect and disk emitters show an image, not a sphere"},
        {"/emitters/1", R"({"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1], "image": "screen.exr"})",
         "scenes/x.json: emitters[1].image: only rect and disk emitters show an image, not a point"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "image": ""})",
         "scenes/x.json: emitters[1].image: must not be empty"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "image": "screen_%04d.exr"})",
         "scenes/x.json: emitters[1].fps: missing: the sequence in emitters[1].image needs its frames per second"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "image": "screen.exr", "fps": 24})",
         "scenes/x.json: emitters[1].fps: only a sequence (a pattern such as screen_%04d.exr in emitters[1].image) takes a frame rate; a video's is its own"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1, "radiance": [1, 1, 1], "fps": 24})",
         "scenes/x.json: emitters[1].fps: only an emitter that shows an image sequence (\"image\": \"screen_%04d.exr\") takes a frame rate"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1, "image": "s_%d.png", "fps": -2})",
         "scenes/x.json: emitters[1].fps: must be in (0, 1000], got -2"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1, "image": 3})",
         "scenes/x.json: emitters[1].image: expected a string, got number"},
        {"/emitters/1", R"({"type": "rect", "center": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1]})",
         "scenes/x.json: emitters[1].radiance: missing required key"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 0, "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].radius: value 0 must be > 0"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, 0, 0], "radius": 1, "radiance": [1, 1, 1]})",
         "scenes/x.json: emitters[1].normal: must not be the zero vector"},
        {"/emitters/1", R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1, "radiance": [-1, 1, 1]})",
         "scenes/x.json: emitters[1].radiance[0]: value -1 must be >= 0"},
        {"/camera", R"({"type": "thin_lens", "position": [0, 1, 4], "look_at": [0, 1, 0], "aperture_radius": 0.1, "focus_distance": -1})",
         "scenes/x.json: camera.focus_distance: value -1 must be > 0"},
        {"/camera", R"({"type": "thin_lens", "position": [0, 1, 4], "look_at": [0, 1, 0], "aperture_radius": 0, "focus_distance": 4})",
         "scenes/x.json: camera.aperture_radius: value 0 must be > 0"},
        {"/camera", R"({"type": "thin_lens", "position": [0, 1, 4], "look_at": [0, 1, 0], "aperture_radius": 0.1})",
         "scenes/x.json: camera.focus_distance: missing required key"},
        {"/environment", R"({"file": "a.exr", "constant": [1, 1, 1]})",
         "scenes/x.json: environment: give exactly one of \"file\" (an image) and \"constant\" (a radiance)"},
        {"/environment", R"({"constant": [1, 1, 1], "exposure": 25})",
         "scenes/x.json: environment.exposure: value 25 is out of range [-20, 20]"},
        {"/environment", R"({"constant": [1, -1, 1]})",
         "scenes/x.json: environment.constant[1]: value -1 must be >= 0"},
        {"/environment", R"({"file": "a.exr", "gamma": 2.2})",
         "scenes/x.json: environment.gamma: unknown key (expected one of: file, constant, rotation_degrees, exposure, background_opacity, background_blur_degrees, keyframes)"},
        {"/extra", "1",
         "scenes/x.json: extra: unknown key (expected one of: $schema, description, camera, materials, objects, emitters, environment)"},
    };
    for (const Mutation& c : cases) {
        INFO("set " << c.pointer << " = " << c.value);
        CHECK(error_with(c.pointer, Json::parse(c.value)) == c.expected);
    }
    CHECK(error_with("/objects/2/shape/children/1/type", "donut")
              .rfind("scenes/x.json: objects[2].shape.children[1].type: unknown node type \"donut\" (expected one of: sphere, plane, box, ", 0) == 0);
    CHECK(error_without("/camera", "position") == "scenes/x.json: camera.position: missing required key");
    CHECK(error_without("/objects/0", "material") == "scenes/x.json: objects[0].material: missing required key");
    Json empty = base_scene();
    empty["objects"] = Json::array();
    empty["emitters"] = Json::array();
    CHECK(error_of_text(empty.dump()) == "scenes/x.json: the scene has no objects and no emitters (point lights are not geometry)");
}

TEST_CASE("scene parser: malformed JSON, overflow, NaN and duplicate keys", "[scene]") {
    std::string text = base_scene().dump(2);
    auto replaced = [&text](const std::string& from, const std::string& to) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    CHECK(error_of_text(replaced("\"radius\": 1\n", "\"radius\": 1e999\n")) ==
          "scenes/x.json: objects[0].shape.radius: malformed JSON: number overflow parsing '1e999'");
    CHECK(error_of_text(replaced("\"radius\": 1\n", "\"radius\": NaN\n")).rfind("scenes/x.json: objects[0].shape.radius: malformed JSON at line", 0) == 0);
    CHECK(error_of_text(replaced("\"gold\": {", "\"sample\": \"../presets/gold.json\", \"gold\": {")) ==
          "scenes/x.json: materials.sample: duplicate key");
    CHECK(error_of_text("{\n  \"camera\": {\"type\": \"pinhole\",,}\n}") ==
          "scenes/x.json: camera.type: malformed JSON at line 2, column 32: syntax error while parsing object key - unexpected ','; "
          "expected string literal");
    CHECK(error_of_text("") == "scenes/x.json: malformed JSON at line 1, column 1: syntax error while parsing value - unexpected end of input; "
                               "expected '[', '{', or a literal");
    CHECK(error_of_text("[1, 2]") == "scenes/x.json: expected an object, got array");

    CHECK(error_loading("tests/scene_data/malformed.json") ==
          "tests/scene_data/malformed.json: camera.position: malformed JSON at line 2, column 63: syntax error while parsing object - "
          "unexpected string literal; expected '}'");
    CHECK(error_loading("tests/scene_data/no_such_scene.json") == "tests/scene_data/no_such_scene.json: cannot open scene file");
    // A preset file's own error names that file and its field.
    CHECK(error_loading("tests/scene_data/bad_preset_reference.json") ==
          "tests/scene_data/nested/bad_roughness_preset.json: roughness: value 1.5 is out of range [0, 1]");
}

TEST_CASE("scene parser: presets inline and from files, paths relative to the scene file", "[scene]") {
    Scene s = lab::scene::load_scene("tests/scene_data/nested/relative_paths.json");
    REQUIRE(s.materials.size() == 2);
    brdf::Material gold = brdf::load_preset("presets/gold.json").material;
    CHECK(s.materials[0].name == "sample");
    CHECK(s.materials[0].source == "presets/gold.json");
    CHECK(s.materials[0].material.metallic == gold.metallic);
    CHECK(s.materials[0].material.roughness == gold.roughness);
    CHECK(s.materials[0].material.albedo[1] == gold.albedo[1]);
    CHECK(s.materials[1].source == "tests/scene_data/nested/local_preset.json");
    CHECK(s.materials[1].material.albedo[2] == 0.75f);
    CHECK(s.materials[1].material.weight_glossy == 0.5f);
    REQUIRE(s.environment.has_value());
    CHECK(s.environment->file == "tests/scene_data/nested/sky/studio.exr");  // existence is the loader's business
    CHECK(s.objects[1].material == 1);

    Scene b = lab::scene::parse_scene(base_scene().dump(), kFile);
    CHECK(b.materials[0].source == "presets/glossy_plastic.json");
    CHECK(b.materials[1].source == "inline");
    CHECK(b.materials[1].material.metallic == 1.0f);
    CHECK(b.materials[1].material.roughness == 0.3f);
    CHECK(b.materials[1].material.weight_diffuse == 0.0f);
    CHECK(b.materials[1].material.albedo[1] == 0.71f);
    CHECK(b.materials[1].material.ior == 1.5f);  // defaults fill what the inline preset leaves out
}

TEST_CASE("scene parser: what a valid file becomes", "[scene]") {
    Scene b = lab::scene::parse_scene(base_scene().dump(), kFile);
    // One material slot per emitter after the declared ones: black, with the radiance as emission.
    REQUIRE(b.emitters.size() == 1);
    CHECK(b.emitters[0].material == 2);
    CHECK(b.materials[2].name == "emitters[0]");
    CHECK(b.materials[2].emission == lab::scene::Vec3(10.0f));
    CHECK(b.materials[2].material.weight_diffuse + b.materials[2].material.weight_glossy + b.materials[2].material.weight_specular +
              b.materials[2].material.weight_transmission == 0.0f);
    CHECK(b.objects[1].shape.path == "objects[1].shape");
    CHECK(b.objects[1].shape.children[0].path == "objects[1].shape.child");
    CHECK(b.objects[2].shape.children[1].path == "objects[2].shape.children[1]");

    // Point lights are lights, not geometry (no slot); a sphere with a material scatters with it.
    Json lit = base_scene();
    lit["emitters"].push_back(Json::parse(R"({"type": "point", "position": [1, 2, 3], "intensity": [4, 5, 6]})"));
    lit["emitters"].push_back(Json::parse(R"({"type": "sphere", "center": [0, -3, 0], "radius": 0.5, "radiance": [1, 2, 3], "material": "gold"})"));
    Scene l = lab::scene::parse_scene(lit.dump(), kFile);
    REQUIRE(l.point_lights.size() == 1);
    CHECK(l.point_lights[0].position == lab::scene::Vec3(1, 2, 3));
    CHECK(l.point_lights[0].intensity == lab::scene::Vec3(4, 5, 6));
    REQUIRE(l.emitters.size() == 2);
    REQUIRE(l.materials.size() == 4);  // sample, gold, emitters[0], emitters[2]
    CHECK(l.emitters[1].material == 3);
    CHECK(l.emitters[1].surface_material == "gold");
    CHECK(l.materials[3].name == "emitters[2]");
    CHECK(l.materials[3].emitter == 1);
    CHECK(l.materials[3].emission == lab::scene::Vec3(1, 2, 3));
    CHECK(l.materials[3].material.metallic == l.materials[1].material.metallic);
    CHECK(l.materials[3].material.weight_glossy == 1.0f);
    CHECK(l.materials[2].material.weight_glossy == 0.0f);  // the plain emitter stays black
    CHECK(l.emitters[0].surface_material.empty());

    Scene t = lab::scene::load_scene("tests/scene_data/combinators.json");
    CHECK(t.camera.type == lab::scene::CameraType::thin_lens);
    CHECK(t.camera.aperture_radius == 0.05f);
    CHECK(t.camera.focus_distance == 6.2f);
    REQUIRE(t.environment.has_value());
    CHECK(t.environment->file.empty());
    CHECK(t.environment->constant == lab::scene::Vec3(0.8f, 0.9f, 1.0f));
    CHECK(t.environment->rotation_degrees == 30.0f);
    CHECK(t.environment->exposure == -1.0f);

    // A plane's normal is normalised; a quarter turn is exact (x goes to -z about +y).
    Json doc = base_scene();
    doc["objects"][0]["shape"] = Json::parse(R"({"type": "plane", "normal": [0, 2, 0], "offset": -1})");
    doc["objects"][1]["shape"] = Json::parse(R"({"type": "rotate", "axis": [0, 3, 0], "degrees": 90, "child": {"type": "sphere", "radius": 1}})");
    doc["objects"][2]["shape"] = Json::parse(R"({"type": "rotate", "euler_degrees": [90, 0, 0], "child": {"type": "sphere", "radius": 1}})");
    Scene r = lab::scene::parse_scene(doc.dump(), kFile);
    const auto& plane = std::get<lab::scene::Plane>(r.objects[0].shape.kind);
    CHECK(plane.normal == lab::scene::Vec3(0.0f, 1.0f, 0.0f));
    CHECK(plane.offset == -1.0f);
    const auto& turn = std::get<lab::scene::Rotate>(r.objects[1].shape.kind).rotation;
    CHECK(turn * lab::scene::Vec3(1, 0, 0) == lab::scene::Vec3(0, 0, -1));
    CHECK(turn * lab::scene::Vec3(0, 1, 0) == lab::scene::Vec3(0, 1, 0));
    const auto& euler = std::get<lab::scene::Rotate>(r.objects[2].shape.kind).rotation;
    CHECK(euler * lab::scene::Vec3(0, 1, 0) == lab::scene::Vec3(0, 0, 1));  // about +x: y goes to z
}

TEST_CASE("scene parser: docs/scene.schema.json names the node types and preset ranges the code has", "[scene]") {
    std::ifstream in("docs/scene.schema.json");
    REQUIRE(in);
    nlohmann::json schema = nlohmann::json::parse(in);
    const nlohmann::json& defs = schema.at("$defs");
    std::vector<std::string> types = defs.at("node").at("properties").at("type").at("enum").get<std::vector<std::string>>();
    CHECK(types == lab::scene::node_type_names());
    // Every node type has its own definition, reached from the node's oneOf.
    std::set<std::string> defined;
    for (const auto& ref : defs.at("node").at("oneOf")) {
        const nlohmann::json& type = defs.at(ref.at("$ref").get<std::string>().substr(8)).at("properties").at("type");
        if (type.contains("const")) defined.insert(type.at("const").get<std::string>());
        else for (const auto& t : type.at("enum")) defined.insert(t.get<std::string>());
    }
    CHECK(defined == std::set<std::string>(types.begin(), types.end()));
    const nlohmann::json& preset = defs.at("preset").at("properties");
    for (const brdf::ScalarParameter& p : brdf::scalar_parameters()) {
        std::string key = p.key;
        INFO(key);
        const nlohmann::json& entry = key.rfind("lobes.", 0) == 0 ? preset.at("lobes").at("properties").at(key.substr(6))
                                      : p.field ? preset.at(key) : preset.at(key).at("items").at("$ref");
        if (!p.field) {  // the albedo: items are "unit", [0, 1]
            CHECK(entry.get<std::string>() == "#/$defs/unit");
            CHECK(p.min == 0.0f);
            CHECK(p.max == 1.0f);
            continue;
        }
        CHECK(entry.at("minimum").get<float>() == p.min);
        CHECK(entry.at("maximum").get<float>() == p.max);
    }
}
