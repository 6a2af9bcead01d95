// The backdrop (kernels/background.h, ibl/background_blur.hpp): what camera rays that escape see of
// the environment, blurred and with an opacity, while the lighting stays the environment's.
//  - the blur of a constant map is that constant; a two-tone map (1 above the horizon, 0 below)
//    blurs to the closed form of the von Mises-Fisher kernel's share above the horizon;
//  - every renderer (host and OpenCL, the path tracer and BDPT) shows that blur on the background;
//  - the pixels whose camera rays all hit a surface are the plain render's to the bit, whatever the
//    blur and opacity; the background pixels scale by the opacity exactly; at opacity 0 they are 0
//    with alpha 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "common/input_error.hpp"
#include "ibl/background_blur.hpp"
#include "ibl/environment.hpp"
#include "opencl/runtime.hpp"
#include "render/aov_layers.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "tests/lobe_material.hpp"
#include "tests/render_inputs.hpp"
#include "tests/worst_difference.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// 1 above the horizon (y > 0), 0 below: the horizon falls on texel edges of the cube's side faces.
lab::ibl::Environment two_tone_environment(int face_size) {
    lab::ibl::LatLongImage image;
    image.width = 256;
    image.height = 128;
    image.rgb.assign(size_t(image.width) * size_t(image.height) * 3, 0.0f);
    for (size_t k = 0; k < size_t(image.width) * size_t(image.height / 2) * 3; ++k) image.rgb[k] = 1.0f;
    lab::ibl::EnvironmentOptions options;
    options.face_size = face_size;
    return lab::ibl::Environment::from_image(image, "two-tone", options);
}

// The blur of the two-tone map seen at elevation beta (radians): the share of the kernel
// exp(kappa (cos gamma - 1)), kappa = 1 / sigma^2, cut at gamma = 4 sigma, above the horizon. Around
// the direction, the ring at angle gamma lies above the horizon where cos phi > -tan(beta) cot(gamma),
// a share acos(clamp(-tan beta cot gamma)) / pi of it; Simpson's rule over gamma.
double two_tone_blur(double beta, double sigma) {
    const double kappa = 1.0 / (sigma * sigma), cut = std::min(kPi, 4.0 * sigma);
    const int steps = 20000;
    double above = 0.0, all = 0.0;
    for (int k = 0; k <= steps; ++k) {
        const double gamma = cut * double(k) / steps;
        const double simpson = (k == 0 || k == steps) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        const double w = simpson * std::exp(kappa * (std::cos(gamma) - 1.0)) * std::sin(gamma);
        const double x = gamma > 0.0 ? std::clamp(-std::tan(beta) * std::cos(gamma) / std::sin(gamma), -1.0, 1.0) : (beta >= 0 ? -1.0 : 1.0);
        above += w * std::acos(x) / kPi;
        all += w;
    }
    return above / all;
}

double degrees(double d) { return d * kPi / 180.0; }

// The two-tone map's blurred backdrop looked up as the kernels look it up (kernels/background.h).
single_source::float3 blurred_lookup(const lab::ibl::Environment& env, const lab::ibl::BlurredCubemap& blurred, single_source::float3 d) {
    ::ibl::EnvironmentMap map = env.map();
    map.face_size = blurred.face_size;
    return ::ibl::environment_radiance_filtered(&map, blurred.texels.data(), d);
}

// A camera at the origin looking down +z at the horizon (40 degrees, square), nothing in view: a
// small ball behind it, so the scene has an object.
const char* const kHorizonScene = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, 1], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "translate", "offset": [0, 0, -10], "child": {"type": "sphere", "radius": 0.5}}}]
})";

}  // namespace

TEST_CASE("Background blur: a constant map stays that constant", "[background][ibl]") {
    const lab::ibl::Environment env = lab::ibl::load_environment("constant:0.25,0.5,2");
    for (float sigma : {2.0f, 10.0f, 90.0f}) {
        const lab::ibl::BlurredCubemap blurred = lab::ibl::blur_cubemap(env.texels(), env.face_size(), sigma);
        for (const single_source::float4& t : blurred.texels) {
            CHECK(t.x == Approx(0.25f).epsilon(1e-6));
            CHECK(t.y == Approx(0.5f).epsilon(1e-6));
            CHECK(t.z == Approx(2.0f).epsilon(1e-6));
        }
    }
}

// The tolerance: the lookup interpolates linearly between texel centres at most h = sigma / 4 apart,
// whose error is at most h^2 / 8 max|F''| = 0.0019 for F(beta) ~ Phi(beta / sigma) (max |Phi''| =
// 0.242 / sigma^2); the source's averaging over texels of h widens the kernel by h^2 / 12, a change of
// sigma by 0.1 %. So 0.005; a sigma 10 % off moves F by more than 0.02 where the test looks.
TEST_CASE("Background blur: a two-tone horizon blurs to the kernel's closed form", "[background][ibl]") {
    const lab::ibl::Environment env = two_tone_environment(64);
    const double sigma = degrees(10.0);
    const lab::ibl::BlurredCubemap blurred = lab::ibl::blur_cubemap(env.texels(), env.face_size(), 10.0f);
    CHECK(blurred.face_size == 46);
    double largest_error = 0.0, largest_change = 0.0;
    for (double beta_degrees : {-25.0, -15.0, -10.0, -5.0, -2.0, 0.0, 2.0, 5.0, 10.0, 15.0, 25.0}) {
        const double beta = degrees(beta_degrees);
        for (double azimuth_degrees : {0.0, 30.0, 45.0, 100.0}) {  // face centres, between faces, across a seam
            const double az = degrees(azimuth_degrees);
            const single_source::float3 d(float(std::sin(az) * std::cos(beta)), float(std::sin(beta)), float(std::cos(az) * std::cos(beta)));
            const double seen = blurred_lookup(env, blurred, d).x;
            const double expected = two_tone_blur(beta, sigma);
            INFO("elevation " << beta_degrees << ", azimuth " << azimuth_degrees << ": " << seen << " against " << expected);
            CHECK(std::fabs(seen - expected) < 0.005);
            largest_error = worse_of(largest_error, std::fabs(seen - expected));
            largest_change = std::max(largest_change, std::fabs(two_tone_blur(beta, 1.1 * sigma) - expected));
        }
    }
    INFO("largest error " << largest_error);
    CHECK(largest_change > 4.0 * 0.005);  // the check can tell a blur 10 % too wide
}

// Every renderer reads the blurred backdrop: the background pixels of a view of the horizon against
// the closed form. Per sample the pixel's jitter spreads the value by at most F' x a pixel's angle
// (1.25 degrees) / sqrt(12) = 0.0144 (F' <= 1 / (sigma sqrt(2 pi)) = 0.040 per degree), so the mean of
// 16 samples is within 4 x 0.0036 of F at the pixel's centre, to which the closed form's 0.005 adds:
// 0.02. The sharp map misses by up to 0.5.
TEST_CASE("Background blur: the host and OpenCL renderers, pt and bdpt, show the blurred horizon", "[background][render][opencl][host]") {
    lab::render::RenderInput input = render_input(std::nullopt, "", 32, lab::render::LightSampling::mis, 3, kHorizonScene);
    input.environment = two_tone_environment(64);
    input.settings.background_blur_degrees = 10.0f;
    lab::opencl::Runtime runtime("");
    std::vector<std::unique_ptr<lab::render::Renderer>> renderers;
    renderers.push_back(std::make_unique<lab::render::HostRenderer>(input));
    renderers.push_back(std::make_unique<lab::render::OpenClRenderer>(runtime, input));
    input.settings.integrator = lab::render::Integrator::bdpt;
    renderers.push_back(std::make_unique<lab::render::HostRenderer>(input));
    renderers.push_back(std::make_unique<lab::render::OpenClRenderer>(runtime, input));
    const double half_height = std::tan(degrees(20.0));
    for (auto& renderer : renderers) {
        const lab::film::ImageRgb image = render_samples(*renderer, 16).image;
        double largest = 0.0;
        for (int y = 0; y < 32; ++y)
            for (int x : {15, 16}) {
                const double dy = (1.0 - 2.0 * (y + 0.5) / 32.0) * half_height, dx = (2.0 * (x + 0.5) / 32.0 - 1.0) * half_height;
                const double beta = std::atan2(dy, std::sqrt(1.0 + dx * dx));
                largest = worse_of(largest, std::fabs(double(image.rgb[3 * size_t(y * 32 + x)]) - two_tone_blur(beta, degrees(10.0))));
            }
        INFO(renderer->device_description() << " " << lab::render::integrator_name(renderer->settings().integrator) << ": largest error " << largest);
        CHECK(largest < 0.02);
    }
}

// Blur and opacity change only what camera rays that escape see: a pixel whose samples all hit the
// model is the plain render's to the bit (the same seeds, paths and MIS weights); a pixel whose
// samples all escape is opacity times the plain one, exactly, when there is no blur (the same
// lookup, one more product); opacity 0 leaves it 0, with alpha 0. BDPT runs on one host thread, so
// its splats add in a fixed order.
TEST_CASE("Background: blur and opacity leave the lighting of the model as it was", "[background][render][opencl][host]") {
    lab::render::RenderInput input = render_input(lobe_material(0.4f, 0.3f, 0.3f, 0), "", 24, lab::render::LightSampling::mis, 11);
    lab::ibl::EnvironmentOptions options;
    options.face_size = 32;
    input.environment = lab::ibl::load_environment("envmaps/courtyard.exr", options);
    lab::opencl::Runtime runtime("");
    std::vector<std::unique_ptr<lab::render::Renderer>> renderers;
    renderers.push_back(std::make_unique<lab::render::HostRenderer>(input));
    renderers.push_back(std::make_unique<lab::render::OpenClRenderer>(runtime, input));
    input.settings.integrator = lab::render::Integrator::bdpt;
    renderers.push_back(std::make_unique<lab::render::HostRenderer>(input, 1));
    for (auto& renderer : renderers) {
        const bool pt = renderer->settings().integrator == lab::render::Integrator::pt;
        INFO(renderer->device_description() << " " << lab::render::integrator_name(renderer->settings().integrator));
        const lab::film::ImageRgb plain = render_samples(*renderer, 4).image;
        const lab::render::FirstHitAovs hits = renderer->first_hit_aovs();
        size_t covered = 0, open = 0;
        for (float c : hits.coverage) covered += c == 1.0f, open += c == 0.0f;
        REQUIRE(covered > 100);
        REQUIRE(open > 20);

        renderer->set_background(0.3f, 8.0f);
        const lab::film::ImageRgb blurred = render_samples(*renderer, 4).image;
        renderer->set_background(0.25f, 0.0f);
        const lab::film::ImageRgb quarter = render_samples(*renderer, 4).image;
        renderer->set_background(0.0f, 0.0f);
        const lab::film::ImageRgb hidden = render_samples(*renderer, 4).image;
        const lab::film::ImageChannel alpha = lab::render::background_alpha_channel(renderer->first_hit_aovs(), 0.0f);

        size_t model_same = 0, sky_changed = 0, sky_scaled = 0, sky_hidden = 0, alpha_right = 0;
        for (size_t p = 0; p < plain.pixel_count(); ++p) {
            bool same = true, changed = false, scaled = true, zero = true;
            for (size_t c = 0; c < 3; ++c) {
                const size_t k = 3 * p + c;
                same = same && blurred.rgb[k] == plain.rgb[k] && quarter.rgb[k] == plain.rgb[k] && hidden.rgb[k] == plain.rgb[k];
                changed = changed || blurred.rgb[k] != plain.rgb[k];
                scaled = scaled && quarter.rgb[k] == 0.25f * plain.rgb[k];
                zero = zero && hidden.rgb[k] == 0.0f;
            }
            if (hits.coverage[p] == 1.0f) {
                model_same += same;
                alpha_right += alpha.values[p] == 1.0f;
            } else if (hits.coverage[p] == 0.0f) {
                sky_changed += changed;
                sky_scaled += scaled;
                sky_hidden += zero;
                alpha_right += alpha.values[p] == 0.0f;
            }
        }
        CHECK(model_same == covered);
        CHECK(sky_changed == open);
        CHECK(alpha_right == covered + open);
        if (pt) {  // BDPT's light paths splat onto pixels beside the model's edge too
            CHECK(sky_scaled == open);
            CHECK(sky_hidden == open);
        }
    }
}

TEST_CASE("Background: the scene's keys and the renderer's checks name the field", "[background][scene]") {
    const std::string scene = R"({"camera": {"type": "pinhole", "position": [0, 0, 3], "look_at": [0, 0, 0]},
      "materials": {"m": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
      "objects": [{"name": "o", "material": "m", "shape": {"type": "sphere", "radius": 1}}],
      "environment": {"constant": [1, 1, 1], "background_opacity": OPACITY, "background_blur_degrees": 12}})";
    auto with = [&](const std::string& opacity) {
        std::string text = scene;
        text.replace(text.find("OPACITY"), 7, opacity);
        return text;
    };
    const lab::scene::Scene s = lab::scene::parse_scene(with("0.25"), "x.json");
    REQUIRE(s.environment);
    CHECK(s.environment->background_opacity == 0.25f);
    CHECK(s.environment->background_blur_degrees == 12.0f);
    CHECK_THROWS_WITH(lab::scene::parse_scene(with("1.5"), "x.json"), Catch::Contains("x.json: environment.background_opacity"));
    lab::render::RenderSettings settings;
    settings.background_blur_degrees = 91.0f;
    CHECK_THROWS_WITH(lab::render::check_render_settings(settings), Catch::StartsWith("--background-blur"));
    settings.background_blur_degrees = 0.0f;
    settings.background_opacity = NAN;
    CHECK_THROWS_WITH(lab::render::check_render_settings(settings), Catch::StartsWith("--background-opacity"));
}
