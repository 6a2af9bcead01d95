// The shadow catcher (kernels/path_tracer.h, docs/environments.md): differential rendering of a
// ground that the camera sees as the backdrop with what the other objects change of its light.
//  - alone under a uniform sky it is the backdrop exactly, on the host and on OpenCL;
//  - under a black ball it darkens by the sky the ball hides, the closed form of a sphere's form
//    factor, 1 - r^2 / h^2 below the ball's centre;
//  - alpha counts it as backdrop; BDPT and light tracing refuse it with one line; a catcher's
//    material shared with another object is an error naming the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "common/input_error.hpp"
#include "opencl/runtime.hpp"
#include "render/aov_layers.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "scene/shadow_catcher.hpp"
#include "scene/test_model.hpp"
#include "tests/render_inputs.hpp"

namespace {

// A white catcher at y = 0 seen from above at 37 degrees, 5 units away, through a 6-degree view of
// the point below BALL (a black ball of radius 0.5 whose centre is 2 above the ground, out of view),
// or nothing else.
std::string catcher_scene(bool ball) {
    std::string objects = R"([{"name": "floor", "material": "catcher", "shadow_catcher": true,
                                "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}})";
    if (ball)
        objects += R"(, {"name": "ball", "material": "black",
                         "shape": {"type": "translate", "offset": [0, 2, 0], "child": {"type": "sphere", "radius": 0.5}}})";
    return R"({"camera": {"type": "pinhole", "position": [0, 3, 4], "look_at": [0, 0, 0], "fov_degrees": 6},
      "materials": {"catcher": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}, "black": {"albedo": [0, 0, 0], "lobes": {"diffuse": 1}}},
      "objects": )" + objects + "]}";
}

lab::render::RenderInput catcher_input(bool ball, int size, uint64_t seed) {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:1,1,1", size, lab::render::LightSampling::mis, seed, catcher_scene(ball));
    return input;
}

}  // namespace

TEST_CASE("Shadow catcher: alone under a uniform sky it is the backdrop exactly, with alpha of the backdrop",
          "[catcher][render][opencl][host]") {
    lab::render::RenderInput input = catcher_input(false, 16, 5);
    lab::opencl::Runtime runtime("");
    std::vector<std::unique_ptr<lab::render::Renderer>> renderers;
    renderers.push_back(std::make_unique<lab::render::HostRenderer>(input));
    renderers.push_back(std::make_unique<lab::render::OpenClRenderer>(runtime, input));
    for (auto& renderer : renderers) {
        INFO(renderer->device_description());
        const lab::film::ImageRgb image = render_samples(*renderer, 8).image;
        size_t exact = 0;
        for (float v : image.rgb) exact += v == 1.0f;
        CHECK(exact == image.rgb.size());
        const lab::render::FirstHitAovs hits = renderer->first_hit_aovs();
        CHECK(*std::max_element(hits.coverage.begin(), hits.coverage.end()) == 0.0f);
        CHECK(*std::min_element(hits.depth.begin(), hits.depth.end()) > 0.0f);  // it was hit, and counts as backdrop
        // opacity 0: the catcher without a shadow adds nothing, so the pixel is 0, alpha 0
        renderer->set_background(0.0f, 0.0f);
        const lab::film::ImageRgb hidden = render_samples(*renderer, 8).image;
        CHECK(*std::max_element(hidden.rgb.begin(), hidden.rgb.end()) == 0.0f);
        CHECK(*std::min_element(hidden.rgb.begin(), hidden.rgb.end()) == 0.0f);
    }
}

// A sphere of radius r whose centre is h above a point, all of it above the horizon, hides the
// cosine-weighted share r^2 / h^2 of that point's sky (its form factor), so a white catcher there
// under a sky of 1 is 1 - r^2 / h^2 = 0.9375 for r = 0.5, h = 2. The 2 x 2 pixels around the view's
// centre see points within 0.07 x 0.11 of it, where the form factor r^2 h / d^3 differs from its
// value below the centre by under 2e-4 on average. The noise: the spread of 8 renders of
// independent seeds (their standard error), with 4 standard errors allowed; a ball 10 % larger
// (0.9244) must lie beyond 8 of them, so the check can tell.
TEST_CASE("Shadow catcher: under a black ball it darkens by the sky the ball hides", "[catcher][render][host]") {
    const double expected = 1.0 - 0.25 / 4.0, larger_ball = 1.0 - 0.55 * 0.55 / 4.0;
    const int runs = 8;
    std::vector<double> means;
    for (int run = 0; run < runs; ++run) {
        lab::render::HostRenderer renderer(catcher_input(true, 4, uint64_t(100 + run)));
        const lab::film::ImageRgb image = render_samples(renderer, 4096).image;
        double sum = 0.0;
        for (int y : {1, 2})
            for (int x : {1, 2}) sum += image.rgb[3 * size_t(y * 4 + x)];
        means.push_back(sum / 4.0);
    }
    double mean = 0.0, spread = 0.0;
    for (double m : means) mean += m / runs;
    for (double m : means) spread += (m - mean) * (m - mean) / (runs - 1);
    const double standard_error = std::sqrt(spread / runs);
    INFO("mean " << mean << " against " << expected << ", standard error " << standard_error);
    CHECK(std::fabs(mean - expected) < 4.0 * standard_error + 2e-4);
    CHECK(std::fabs(larger_ball - expected) > 8.0 * standard_error);
}

TEST_CASE("Shadow catcher: only the path tracer renders it; a shared material and a bad flag are errors", "[catcher][scene]") {
    lab::render::RenderInput input = catcher_input(true, 4, 1);
    input.settings.integrator = lab::render::Integrator::bdpt;
    CHECK_THROWS_WITH(lab::render::HostRenderer(input), Catch::Contains("--integrator: the shadow catcher") &&
                                                          Catch::Contains("path tracer only"));
    std::string shared = catcher_scene(true);
    shared.replace(shared.find("\"material\": \"black\""), 19, "\"material\": \"catcher\"");
    CHECK_THROWS_WITH(lab::scene::parse_scene(shared, "x.json"), Catch::StartsWith("x.json: objects[0].material: a shadow catcher needs a material of its own"));
    std::string bad = catcher_scene(false);
    bad.replace(bad.find("true"), 4, "1");
    CHECK_THROWS_WITH(lab::scene::parse_scene(bad, "x.json"), Catch::StartsWith("x.json: objects[0].shadow_catcher: expected true or false"));
}

TEST_CASE("Shadow catcher: --shadow-catcher's plane lies under the lowest bounded object", "[catcher][scene]") {
    const lab::scene::Scene scene = lab::scene::parse_scene(catcher_scene(true), "x.json");
    const lab::scene::Scene with = lab::scene::with_shadow_catcher(scene);
    REQUIRE(with.objects.size() == scene.objects.size() + 1);
    const lab::scene::Object& catcher = with.objects.back();
    CHECK(catcher.shadow_catcher);
    CHECK(catcher.material == int(with.materials.size()) - 1);
    const auto* plane = std::get_if<lab::scene::Plane>(&catcher.shape.kind);
    REQUIRE(plane);
    CHECK(plane->offset == Approx(-1.5f));  // the ball's bottom, 2 - 0.5 (the scene's own catcher is left out)

    // the test model's ground becomes the catcher, its plane kept
    const lab::scene::Scene model = lab::scene::load_test_model();
    const lab::scene::Scene caught = lab::scene::with_shadow_catcher(model);
    CHECK(caught.objects.size() == model.objects.size());
    size_t grounds = 0;
    for (const lab::scene::Object& o : caught.objects) grounds += o.name == lab::scene::kGroundObject;
    CHECK(grounds == 0);
    const auto* ground_plane = std::get_if<lab::scene::Plane>(&caught.objects.back().shape.kind);
    REQUIRE(ground_plane);
    CHECK(caught.objects.back().shadow_catcher);
    CHECK(ground_plane->offset == 0.0f);
}
