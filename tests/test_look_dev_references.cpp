// The look-dev references (scene/look_dev_references): the grey ball is 18 % grey where it matters,
// in a render; the chart's greys are the Munsell values they are named for; adding references keeps
// every slot of the scene where it was.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "render/host_renderer.hpp"
#include "scene/load_scene.hpp"
#include "scene/look_dev_references.hpp"
#include "scene/test_model.hpp"

TEST_CASE("Look-dev references: the grey ball alone under a white sky reflects 0.18", "[references][render][host]") {
    // A convex Lambert ball under a uniform sky of radiance 1 sees nothing but the sky: its radiance
    // is its albedo, 0.18, everywhere (the white furnace). The test model's objects are left out.
    lab::scene::Scene scene = lab::scene::load_test_model();
    scene.objects.clear();
    scene = lab::scene::with_look_dev_references(scene, lab::scene::parse_look_dev_references("grey", "--references"), 1.0f);
    REQUIRE(scene.objects.size() == 1);
    lab::render::RenderInput input;
    input.scene = scene;
    input.environment = lab::ibl::Environment::constant(brdf::float3(1.0f), "white", {});
    const int size = 96;
    input.settings.width = input.settings.height = size;
    lab::render::HostRenderer renderer(input);
    renderer.add_samples(64);
    const lab::film::ImageRgb image = renderer.image();

    // The ball's centre lies on the plane at 0.7 of the way to the look-at point, at (half width -
    // 0.54 half height, -0.72 half height) of the view there: in pixels, on a square image,
    // x = (1 + 0.46) / 2, y = (1 + 0.72) / 2 of the size; its radius 0.14 half heights, 0.07 of
    // the size. The pixels within 0.6 of that radius see only the ball.
    const double cx = 0.73 * size, cy = 0.86 * size, r = 0.6 * 0.07 * size;
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) > r) continue;
            const double v = (image.at(x, y)[0] + image.at(x, y)[1] + image.at(x, y)[2]) / 3.0;  // the channels are one estimate
            sum += v;
            sum2 += v * v;
            ++n;
        }
    REQUIRE(n >= 40);
    const double mean = sum / n, variance = std::max(0.0, sum2 / n - mean * mean);
    // Four standard errors of the mean over the pixels (each an independent estimate), and float
    // rounding.
    const double bound = 4.0 * std::sqrt(variance / n) + 1e-5;
    INFO("mean " << mean << " over " << n << " pixels, bound " << bound);
    CHECK(std::fabs(mean - double(lab::scene::kGreyBallAlbedo)) <= bound);
    // And the sky around it is the sky.
    CHECK(image.at(2, 2)[0] == Approx(1.0f).margin(1e-6));
}

TEST_CASE("Look-dev references: the chart's greys are their Munsell values", "[references]") {
    // The neutral patches are Munsell N9.5, N8, N6.5, N5, N3.5 and N2; ASTM D1535's polynomial
    // gives the luminance factor Y of a Munsell value V. Their albedos (the published sRGB, decoded)
    // match it to 0.02: a transcription error or a missing decode (sRGB 122 read as 0.48, not 0.19)
    // is far beyond.
    const double values[6] = {9.5, 8.0, 6.5, 5.0, 3.5, 2.0};
    for (int i = 0; i < 6; ++i) {
        const double v = values[i];
        const double y = (1.1914 * v - 0.22533 * v * v + 0.23352 * v * v * v - 0.020484 * std::pow(v, 4) + 0.00081939 * std::pow(v, 5)) / 100.0;
        const lab::scene::ColorCheckerPatch& p = lab::scene::kColorCheckerPatches[size_t(18 + i)];
        const double luminance = 0.2126 * lab::film::srgb_decode(p.srgb8[0] / 255.0f) + 0.7152 * lab::film::srgb_decode(p.srgb8[1] / 255.0f) +
                                 0.0722 * lab::film::srgb_decode(p.srgb8[2] / 255.0f);
        INFO(p.name << ": Y " << luminance << ", Munsell N" << v << " " << y);
        CHECK(std::fabs(luminance - y) < 0.02);
    }
}

TEST_CASE("Look-dev references: added after every slot of the scene, which keep their indices", "[references]") {
    const lab::scene::Scene plain = lab::scene::load_scene("scenes/cornell_box.json");
    REQUIRE_FALSE(plain.emitters.empty());
    const lab::scene::Scene with =
        lab::scene::with_look_dev_references(plain, lab::scene::parse_look_dev_references("all", "--references"), 4.0f / 3.0f);
    REQUIRE(with.objects.size() == plain.objects.size() + 26);
    REQUIRE(with.materials.size() == plain.materials.size() + 26);
    auto same = [](const brdf::Material& a, const brdf::Material& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (size_t i = 0; i < plain.objects.size(); ++i) {
        CHECK(with.objects[i].name == plain.objects[i].name);
        CHECK(with.objects[i].material == plain.objects[i].material);
    }
    for (size_t s = 0; s < plain.materials.size(); ++s) {
        CHECK(with.materials[s].name == plain.materials[s].name);
        CHECK(same(with.materials[s].material, plain.materials[s].material));
        CHECK(with.materials[s].emitter == plain.materials[s].emitter);
    }
    for (size_t k = 0; k < plain.emitters.size(); ++k) CHECK(with.emitters[k].material == plain.emitters[k].material);
    for (size_t i = plain.objects.size(); i < with.objects.size(); ++i) {
        CHECK(size_t(with.objects[i].material) >= plain.materials.size());
        CHECK(with.materials[size_t(with.objects[i].material)].name == with.objects[i].name);
    }
    // The references' own: the chrome ball a mirror of chromium's F0, the grey ball 18 % Lambert.
    auto slot_of = [&](const std::string& name) {
        for (const lab::scene::Object& o : with.objects)
            if (o.name == name) return with.materials[size_t(o.material)].material;
        FAIL("no object " << name);
        return brdf::Material{};
    };
    CHECK(slot_of("reference_grey").albedo[1] == lab::scene::kGreyBallAlbedo);
    CHECK(slot_of("reference_chrome").weight_specular == 1.0f);
    CHECK(slot_of("reference_chrome").metallic == 1.0f);
    CHECK(slot_of("reference_chart_neutral_6_5").albedo[0] == lab::film::srgb_decode(160.0f / 255.0f));

    CHECK(lab::scene::parse_look_dev_references("chrome,chart", "--references").color_chart);
    CHECK_FALSE(lab::scene::parse_look_dev_references("none", "--references").any());
    CHECK_THROWS_WITH(lab::scene::parse_look_dev_references("chrome,teapot", "--references"),
                      "--references: unknown reference \"teapot\" (none, all, or a list of chrome, grey, chart, catcher)");
}
