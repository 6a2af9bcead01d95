// The scene time (docs/scenes.md, "Time"): keyframes interpolated linearly and by Catmull-Rom
// against values computed by hand, at keyframes, between them and past both ends; the camera and the
// environment's rotation of a scene at a time; and every kind of bad keyframes as one line naming
// the scene file and the field.
#include <catch2/catch.hpp>

#include <string>

#include "common/input_error.hpp"
#include "scene/json_fields.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_time.hpp"

namespace {

const char* const kTimeFile = "scenes/t.json";

// A scene whose camera and environment are keyframed; each case replaces a part of it.
lab::scene::Json animated_scene() {
    return lab::scene::Json::parse(R"({
      "camera": {"type": "pinhole", "up": [0, 1, 0],
                 "keyframes": {"interpolation": "catmull_rom", "times": [0, 1, 3],
                               "position": [[0, 0, 5], [10, 1, 5], [4, 2, 5]],
                               "look_at": [[0, 0, 0], [0, 0, 0], [0, 0, 0]],
                               "fov_degrees": [40, 50, 30]}},
      "materials": {"white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}}},
      "objects": [{"name": "ball", "material": "white", "shape": {"type": "sphere", "radius": 1}}],
      "environment": {"constant": [1, 1, 1], "keyframes": {"times": [0, 1, 3], "rotation_degrees": [0, 10, 4]}}
    })");
}

lab::scene::Scene parsed(const lab::scene::Json& doc) { return lab::scene::parse_scene(doc.dump(), kTimeFile); }

std::string time_error(const lab::scene::Json& doc, double t = 0.0) {
    try {
        lab::scene::scene_at_time(parsed(doc), t);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

lab::scene::Json with(const char* pointer, const char* value) {
    lab::scene::Json doc = animated_scene();
    doc[lab::scene::Json::json_pointer(pointer)] = lab::scene::Json::parse(value);
    return doc;
}

}  // namespace

TEST_CASE("scene time: linear keyframes between, at and past their times", "[scene]") {
    // rotation 0, 10, 4 at times 0, 1, 3
    const lab::scene::Scene scene = parsed(animated_scene());
    auto rotation = [&](double t) { return double(lab::scene::scene_at_time(scene, t).environment->rotation_degrees); };
    CHECK(rotation(-1.0) == 0.0);  // held before the first keyframe
    CHECK(rotation(0.0) == 0.0);
    CHECK(rotation(0.5) == 5.0);
    CHECK(rotation(1.0) == 10.0);
    CHECK(rotation(2.0) == 7.0);  // the second segment: 10 + (4 - 10) / 2
    CHECK(rotation(2.5) == 5.5);
    CHECK(rotation(3.0) == 4.0);
    CHECK(rotation(7.0) == 4.0);  // held after the last
}

TEST_CASE("scene time: Catmull-Rom keyframes against the Hermite form by hand", "[scene]") {
    // position.x: 0, 10, 4 at times 0, 1, 3. Tangents: (10 - 0) / 1 = 10 at the first keyframe (one-sided),
    // (4 - 0) / 3 at the second, (4 - 10) / 2 = -3 at the last (one-sided).
    const lab::scene::Scene scene = parsed(animated_scene());
    auto x = [&](double t) { return double(lab::scene::camera_at(scene.camera, t).position.x); };
    CHECK(x(-2.0) == 0.0);
    CHECK(x(0.0) == 0.0);
    // s = 1/2 on [0, 1], h = 1: 0.5 * 0 + 0.125 * 10 + 0.5 * 10 - 0.125 * 4/3
    CHECK(x(0.5) == Approx(1.25 + 5.0 - 1.0 / 6.0).epsilon(1e-6));
    CHECK(x(1.0) == 10.0);
    // s = 1/2 on [1, 3], h = 2: 0.5 * 10 + 0.125 * 2 * 4/3 + 0.5 * 4 - 0.125 * 2 * (-3)
    CHECK(x(2.0) == Approx(5.0 + 1.0 / 3.0 + 2.0 + 0.75).epsilon(1e-6));
    // s = 3/4 on [1, 3]: h00 = 0.15625, h10 = 0.046875, h01 = 0.84375, h11 = -0.140625
    CHECK(x(2.5) == Approx(1.5625 + 0.125 + 3.375 + 0.84375).epsilon(1e-6));
    CHECK(x(3.0) == 4.0);
    CHECK(x(9.0) == 4.0);
    // the other tracks alike: y is linear in time's keyframes 0, 1, 2 over 0, 1, 3, fov 40, 50, 30
    CHECK(lab::scene::camera_at(scene.camera, 1.0).fov_degrees == 50.0f);
    CHECK(lab::scene::camera_at(scene.camera, 0.0).look_at == lab::scene::Vec3(0.0f));
    // a still field keeps its value
    CHECK(lab::scene::camera_at(scene.camera, 2.0).up == lab::scene::Vec3(0.0f, 1.0f, 0.0f));

    // On evenly spaced keyframes Catmull-Rom reproduces a quadratic on the inner segments: t^2 at
    // 0, 1, 2, 3 gives 2.25 at 1.5 (its ends, with one-sided tangents, do not).
    lab::scene::Json doc = animated_scene();
    doc["camera"]["keyframes"] = lab::scene::Json::parse(R"({"interpolation": "catmull_rom", "times": [0, 1, 2, 3],
        "position": [[0, 0, 5], [1, 0, 5], [4, 0, 5], [9, 0, 5]], "look_at": [[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]]})");
    const lab::scene::Scene even = parsed(doc);
    CHECK(double(lab::scene::camera_at(even.camera, 1.5).position.x) == 2.25);
    CHECK(double(lab::scene::camera_at(even.camera, 1.25).position.x) == 1.5625);
}

TEST_CASE("scene time: a scene without keyframes is the same at every time", "[scene]") {
    lab::scene::Json doc = animated_scene();
    doc["camera"] = lab::scene::Json::parse(R"({"type": "pinhole", "position": [0, 1, 4], "look_at": [0, 0, 0]})");
    doc["environment"] = lab::scene::Json::parse(R"({"constant": [1, 1, 1], "rotation_degrees": 30})");
    const lab::scene::Scene scene = parsed(doc);
    CHECK_FALSE(lab::scene::is_animated(scene));
    const lab::scene::Scene later = lab::scene::scene_at_time(scene, 12.5);
    CHECK(later.camera.position == scene.camera.position);
    CHECK(later.environment->rotation_degrees == 30.0f);
    CHECK(lab::scene::is_animated(parsed(animated_scene())));
}

TEST_CASE("scene time: bad keyframes name the scene file and the field", "[scene]") {
    struct Case {
        const char* pointer;
        const char* value;
        const char* expected;
    };
    const Case cases[] = {
        {"/camera/keyframes/times", "[0, 3, 1]",
         "scenes/t.json: camera.keyframes.times[2]: time 1 is not after the one before it (3): times must increase strictly"},
        {"/camera/keyframes/times", "[0, 1, 1]",
         "scenes/t.json: camera.keyframes.times[2]: time 1 is not after the one before it (1): times must increase strictly"},
        {"/camera/keyframes/times/1", R"("1")", "scenes/t.json: camera.keyframes.times[1]: expected a number, got string"},
        {"/camera/keyframes/times", "[0, 1]",
         "scenes/t.json: camera.keyframes.times: 2 keyframes, but catmull_rom needs at least 3 (2 make a line: use linear)"},
        {"/environment/keyframes/times", "[0]",
         "scenes/t.json: environment.keyframes.times: 1 keyframes, but keyframes need at least 2 (one value is not animated: give it in place)"},
        {"/camera/keyframes/position", "[[0, 0, 5], [10, 1, 5]]", "scenes/t.json: camera.keyframes.position: 2 keyframes, but times has 3"},
        {"/environment/keyframes/rotation_degrees", "[0, 10, 4, 5]",
         "scenes/t.json: environment.keyframes.rotation_degrees: 4 keyframes, but times has 3"},
        {"/camera/keyframes/position/1", "[10, 1]", "scenes/t.json: camera.keyframes.position[1]: expected an array of 3 numbers"},
        {"/camera/keyframes/fov_degrees/2", "180", "scenes/t.json: camera.keyframes.fov_degrees[2]: value 180 is out of range (0, 180)"},
        {"/environment/keyframes/rotation_degrees/1", "[10]",
         "scenes/t.json: environment.keyframes.rotation_degrees[1]: expected a number, got array"},
        {"/camera/keyframes/interpolation", R"("cubic")",
         "scenes/t.json: camera.keyframes.interpolation: unknown interpolation \"cubic\" (expected one of: linear, catmull_rom)"},
        {"/camera/keyframes/aperture_radius", "[1, 1, 1]",
         "scenes/t.json: camera.keyframes.aperture_radius: unknown key (expected one of: interpolation, times, position, look_at, up, fov_degrees)"},
        {"/camera/keyframes", R"({"times": [0, 1]})", "scenes/t.json: camera.keyframes: keyframes nothing: give at least one of position, look_at, up, fov_degrees"},
        {"/camera/position", "[0, 0, 5]", "scenes/t.json: camera.position: is keyframed too (camera.keyframes.position): give it in one place"},
        {"/environment/rotation_degrees", "10",
         "scenes/t.json: environment.rotation_degrees: is keyframed too (environment.keyframes.rotation_degrees): give it in one place"},
        // a keyframe that is no camera: position on look_at at the second keyframe
        {"/camera/keyframes/position/1", "[0, 0, 0]",
         "scenes/t.json: camera.keyframes: at t = 1 s the camera's look_at equals camera.position: there is no view direction"},
    };
    for (const Case& c : cases) {
        INFO("set " << c.pointer << " = " << c.value);
        CHECK(time_error(with(c.pointer, c.value)) == c.expected);
    }
    lab::scene::Json no_position = animated_scene();
    no_position["camera"]["keyframes"].erase("position");
    CHECK(time_error(no_position) == "scenes/t.json: camera.position: missing required key");
    // NaN is not JSON: the parser names the field it was reading
    std::string text = animated_scene().dump();
    text.replace(text.find("[0,1,3]"), 7, "[0,NaN,3]");
    std::string nan_error;
    try {
        lab::scene::parse_scene(text, kTimeFile);
    } catch (const lab::InputError& e) {
        nan_error = e.what();
    }
    CHECK(nan_error.rfind("scenes/t.json: camera.keyframes.times[1]: malformed JSON at line 1", 0) == 0);

    // Each keyframe is a camera, but the spline between them overshoots: fov 179, 179, 1 at 0, 1, 2
    // has tangent 0 at the first keyframe and -89 at the second, so at t = 0.5 it is
    // 179 - 89 * (0.125 - 0.25) = 190.125.
    lab::scene::Json overshoot = animated_scene();
    overshoot["camera"]["keyframes"]["times"] = lab::scene::Json::parse("[0, 1, 2]");
    overshoot["camera"]["keyframes"]["fov_degrees"] = lab::scene::Json::parse("[179, 179, 1]");
    CHECK(time_error(overshoot, 0.0) == "(no error)");
    CHECK(time_error(overshoot, 0.5) ==
          "scenes/t.json: camera.keyframes: at t = 0.5 s the camera's fov_degrees value 190.125 is out of range (0, 180)");
}
