// Closed-form scenes after pbrt-v4's integrator tests, shared by the path tracer's tests
// (test_render_closed_forms.cpp) and BDPT's (test_bdpt_closed_forms.cpp). In each the exact pixel value
// is known; the first three have two lights of unequal power, so the two selection modes are
// different estimators of it:
//  - inside a Lambert sphere of reflectance rho = 0.5 and radius R = 1 that also emits Le = 0.25 (a
//    reflecting emitter seen from inside), with a point light of intensity I = pi/2 at its centre:
//    L = Le + (rho / pi) I / R^2 + rho L, so L = (0.25 + 0.25) / (1 - 0.5) = 1 everywhere;
//  - point lights of intensity pi/4 and 3 pi/4 at the centre of a Lambert sphere of reflectance 0.5,
//    radius 1: the wall receives E = I / R^2 directly and rho L from the rest of the wall,
//    L = (rho / pi) E / (1 - rho) = 1;
//  - a black emissive sphere of radius r and radiance Le at the centre of that Lambert sphere: the
//    wall sees it in a cone of sin^2 = s = (r / R)^2 and the wall in the rest of its hemisphere,
//    L = rho (Le s + L (1 - s)), so L = rho Le s / (1 - rho (1 - s)). A point light hidden inside
//    the black sphere adds nothing but competes for the light samples;
//  - an endless Lambert plane of reflectance rho = 0.5 under a constant environment L = 1, seen from
//    above (every pixel sees the plane): it receives E = pi L from its upper hemisphere, so
//    L = (rho / pi) E = rho L = 0.5;
//  - a white furnace: a closed Lambert object of reflectance 1 (a torus, which sees itself) under a
//    constant environment L = 1 and nothing else: every path ends in the environment with its
//    throughput unchanged, so every pixel, the object's and the environment's seen past it, is L = 1.
// The last two have one light, the environment, so both selection modes are the same estimator
// (BDPT's light subpaths from an environment start on a disk of the scene's bounding sphere, which
// the endless plane does not have). Every pixel has the same expectation, so the test compares the image mean with the exact value;
// it must be within 1 %, and the test first requires the mean's own standard error (from the spread
// of the pixel means, an estimate independent of the expected value) to be small enough that a
// 1 % error would show.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>

#include "render/renderer.hpp"
#include "tests/render_inputs.hpp"

namespace closed_forms {

// The sanitized build (DTOADQ_SANITIZED_TESTS) runs the host cases to put the integrators' host
// code under ASan and UBSan, with a quarter of the paths: its means' standard errors are twice as
// large, and so is its bound (2 % instead of 1 %, still four of its own standard errors). The
// plain build's run states the closed forms' precision.
#ifdef DTOADQ_SANITIZED_TESTS
constexpr int kPathDivisor = 4;
#else
constexpr int kPathDivisor = 1;
#endif
// The relative error a check allows, `plain` at the full budget: sqrt(divisor) times wider with
// 1 / divisor of the paths, as the standard errors are.
inline double bound(double plain, int divisor = kPathDivisor) { return plain * std::sqrt(double(divisor)); }

using lab::render::LightSelection;
using lab::render::LightSampling;

// The Lambert reflector of every case: reflectance 0.5, no retro-reflection, no subsurface.
inline const char* kWall = R"("wall": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0})";

// A Lambert shell: the cavity of radius 1 is outside the solid, so its wall faces the centre.
inline const char* kShell = R"({"name": "shell", "material": "wall", "shape": {"type": "subtraction", "children": [
    {"type": "sphere", "radius": 1.25}, {"type": "sphere", "radius": 1}]}})";

inline std::string reflecting_emitter_scene() {
    return std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_degrees": 60},
      "materials": {)") + kWall + R"(},
      "emitters": [{"center": [0, 0, 0], "radius": 1, "radiance": [0.25, 0.25, 0.25], "material": "wall"},
                   {"type": "point", "position": [0, 0, 0], "intensity": [1.57079633, 1.57079633, 1.57079633]}]})";
}

inline std::string point_light_scene() {
    return std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_degrees": 60},
      "materials": {)") + kWall + R"(}, "objects": [)" + kShell + R"(],
      "emitters": [{"type": "point", "position": [0, 0, 0], "intensity": [0.785398163, 0.785398163, 0.785398163]},
                   {"type": "point", "position": [0, 0, 0], "intensity": [2.35619449, 2.35619449, 2.35619449]}]})";
}

// The camera looks away from the small sphere, so every pixel sees the wall.
inline std::string black_sphere_scene() {
    return std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 0.5], "look_at": [0, 0, 1], "fov_degrees": 40},
      "materials": {)") + kWall + R"(}, "objects": [)" + kShell + R"(],
      "emitters": [{"center": [0, 0, 0], "radius": 0.2, "radiance": [1, 1, 1]},
                   {"type": "point", "position": [0, 0, 0], "intensity": [0.05, 0.05, 0.05]}]})";
}

// Looks down at the plane: the view's rays leave the camera 25 to 65 degrees below the horizon.
inline std::string lambert_plane_scene() {
    return std::string(R"({"camera": {"type": "pinhole", "position": [0, 2, 0], "look_at": [0, 0, -2], "fov_degrees": 40},
      "materials": {)") + kWall + R"(}, "objects": [{"name": "ground", "material": "wall", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}}]})";
}

// A torus tilted towards the camera, which sees its hole and the environment around it.
inline std::string white_furnace_scene() {
    return R"({"camera": {"type": "pinhole", "position": [0, 0, 2], "look_at": [0, 0, 0], "fov_degrees": 40},
      "materials": {"white": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0}},
      "objects": [{"name": "torus", "material": "white", "shape": {"type": "rotate", "euler_degrees": [60, 0, 0],
                   "child": {"type": "torus", "major_radius": 0.45, "minor_radius": 0.2}}}]})";
}

struct Case {
    std::string name;
    std::string scene;
    double expected;
    std::string env;  // "constant:R,G,B"; empty: none
};

struct Mean {
    double value = 0.0, standard_error = 0.0;
};

// The mean over pixels of the green channel, and its standard error from the pixels' spread.
inline Mean image_mean(const lab::film::ImageRgb& image) {
    double sum = 0.0, sum2 = 0.0;
    size_t n = image.pixel_count();
    for (size_t p = 0; p < n; ++p) {
        double v = image.rgb[3 * p + 1];
        sum += v;
        sum2 += v * v;
    }
    Mean m;
    m.value = sum / double(n);
    m.standard_error = std::sqrt(std::max(0.0, sum2 / double(n) - m.value * m.value) / double(n - 1));
    return m;
}

inline std::vector<Case> cases() {
    double s = 0.2 * 0.2;
    return {{"inside a reflecting emitter", reflecting_emitter_scene(), 1.0, ""},
            {"point lights at the centre of a Lambert sphere", point_light_scene(), 1.0, ""},
            {"black emissive sphere at the centre of a Lambert sphere", black_sphere_scene(), 0.5 * s / (1.0 - 0.5 * (1.0 - s)), ""},
            {"endless Lambert plane under a constant environment", lambert_plane_scene(), 0.5, "constant:1,1,1"},
            {"white furnace: a Lambert torus of reflectance 1 under a constant environment", white_furnace_scene(), 1.0, "constant:1,1,1"}};
}

inline lab::render::RenderInput case_input(const Case& c, LightSelection selection, int size) {
    lab::render::RenderInput input = render_input(std::nullopt, c.env, size, LightSampling::mis, 7, c.scene);
    input.light_selection = selection;
    input.settings.max_depth = 64;  // 0.5^64: no truncation the test could see
    return input;
}

inline void check_case(const Case& c, LightSelection selection, lab::render::Renderer& renderer, int plain_spp) {
    const int spp = plain_spp / kPathDivisor;
    RenderResult r = render_samples(renderer, spp);
    Mean m = image_mean(r.image);
    INFO(c.name << " (" << lab::render::light_selection_name(selection) << " selection, " << renderer.device_description() << "): mean "
                << m.value << " +- " << m.standard_error << ", exact " << c.expected << ", " << spp << " spp");
    CHECK(r.stats.nonfinite_samples == 0);
    REQUIRE(m.standard_error < bound(0.0025) * c.expected);  // a 1 % error is at least 4 standard errors
    CHECK(std::fabs(m.value - c.expected) < bound(0.01) * c.expected);
}

}  // namespace closed_forms

