// BDPT and the light tracer as renderers: the t = 1 connection's edge cases (splats at the film's
// border, light vertices behind the camera, points outside a thin lens's view), the same seed
// giving the same image, and non-finite contributions counted. Their agreement with the path tracer
// on every bundled scene is tests/test_integrator_agreement.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "film/image_stats.hpp"
#include "kernels/host.hpp"
#include "render/camera_setup.hpp"
#include "render/host_renderer.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"
#include "validation/uniform_random.hpp"

namespace {

using brdf::float3;

kernel::Camera test_camera(float aperture) {
    lab::scene::Camera c;
    c.type = aperture > 0.0f ? lab::scene::CameraType::thin_lens : lab::scene::CameraType::pinhole;
    c.position = float3(0.0f, 1.0f, 5.0f);
    c.look_at = float3(0.0f, 1.0f, 0.0f);
    c.fov_degrees = 40.0f;
    c.aperture_radius = aperture;
    c.focus_distance = 5.0f;
    return lab::render::make_camera(c, 32, 24, "test");
}

float splat_total(const std::vector<unsigned>& splat) {
    float sum = 0.0f;
    for (unsigned bits : splat) sum += kernel::film_bits_to_float(bits);
    return sum;
}

}  // namespace

TEST_CASE("BDPT t = 1: splats at the film's border land in its edge pixels, beyond it nowhere", "[render][bdpt][splat]") {
    std::vector<unsigned> splat(32 * 24 * 3, 0u);
    const float3 one(1.0f);
    kernel::film_splat(splat.data(), 32, 24, std::nextafter(32.0f, 0.0f), std::nextafter(24.0f, 0.0f), one);
    CHECK(kernel::film_bits_to_float(splat[3 * (23 * 32 + 31)]) == 1.0f);
    kernel::film_splat(splat.data(), 32, 24, 0.0f, 0.0f, one);
    CHECK(kernel::film_bits_to_float(splat[0]) == 1.0f);
    for (float x : {32.0f, -1e-6f})
        for (float y : {0.5f, 23.5f}) kernel::film_splat(splat.data(), 32, 24, x, y, one);
    kernel::film_splat(splat.data(), 32, 24, 5.0f, 24.0f, one);
    kernel::film_splat(splat.data(), 32, 24, 5.0f, -1e-6f, one);
    CHECK(splat_total(splat) == 6.0f);  // the two inside, three channels each
}

TEST_CASE("BDPT t = 1: lens connections from behind the camera or outside its view are not visible", "[render][bdpt][splat]") {
    lab::validation::UniformRandom rng(11);
    for (float aperture : {0.0f, 0.2f}) {
        kernel::Camera cam = test_camera(aperture);
        int visible = 0, visible_outside_pinhole_view = 0;
        for (int i = 0; i < 20000; ++i) {
            // points around the camera, in front of and behind it, inside and well outside the view
            float3 p(float(rng.next_double() * 16.0 - 8.0), float(rng.next_double() * 16.0 - 7.0), float(rng.next_double() * 20.0 - 10.0));
            brdf::float2 u(float(rng.next_double()), float(rng.next_double()));
            kernel::CameraSample cs = kernel::camera_sample_wi(&cam, p, u);
            float depth = glm::dot(p - float3(0.0f, 1.0f, 5.0f), float3(0.0f, 0.0f, -1.0f));
            if (depth <= 0.0f) {
                INFO("behind the camera: " << p.x << " " << p.y << " " << p.z);
                CHECK(cs.visible == 0);  // the thin lens's points lie in its plane, so behind it is behind all of them
                continue;
            }
            brdf::float2 raster;
            bool in_pinhole_view = kernel::camera_raster(&cam, float3(0.0f, 1.0f, 5.0f), glm::normalize(p - float3(0.0f, 1.0f, 5.0f)), &raster) > 0.0f &&
                                   kernel::camera_raster_inside(&cam, raster);
            if (!cs.visible) continue;
            ++visible;
            INFO("aperture " << aperture << ", raster " << cs.raster.x << " " << cs.raster.y);
            CHECK((cs.raster.x >= 0.0f && cs.raster.x < 32.0f && cs.raster.y >= 0.0f && cs.raster.y < 24.0f));
            CHECK(cs.importance > 0.0f);
            if (!in_pinhole_view) ++visible_outside_pinhole_view;
        }
        CHECK(visible > 100);
        // a pinhole sees exactly its view; a thin lens also sees, from part of its lens, points just outside it
        if (aperture == 0.0f) CHECK(visible_outside_pinhole_view == 0);
        else CHECK(visible_outside_pinhole_view > 0);
    }
}

namespace {

lab::render::RenderInput scene_input(const std::string& path, lab::render::Integrator integrator, int size, uint64_t seed) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    lab::render::RenderInput input = render_input(std::nullopt, "", size, lab::render::LightSampling::mis, seed, text.str());
    input.settings.integrator = integrator;
    return input;
}

}  // namespace

TEST_CASE("BDPT: the same seed gives the same image", "[render][bdpt][seed]") {
    // One thread: the splats land in one order, so the image is bit-identical. With several threads
    // (and on OpenCL) the splat buffer's sums round in the order splats arrive: equal to rounding.
    // The light-vertex cache is keyed by the sample index alone: a pass split into launches of 64
    // pixels (each tracing the sample's pool again, the first splatting it) gives the same bits.
    // vcm's merges add in the hash grid's order, built by one work-item in the cache's order.
    for (lab::render::Integrator integrator : {lab::render::Integrator::bdpt, lab::render::Integrator::bdpt_cache, lab::render::Integrator::vcm}) {
        INFO(lab::render::integrator_name(integrator));
        std::vector<float> images[4];
        for (int run = 0; run < 4; ++run) {
            lab::render::HostRenderer renderer(scene_input("scenes/cornell_box.json", integrator, 12, run == 2 ? 8 : 7), 1);
            if (run == 3) renderer.set_launch_pixels(64);
            images[run] = render_samples(renderer, 4).image.rgb;
        }
        REQUIRE(images[0].size() == images[1].size());
        CHECK(std::memcmp(images[0].data(), images[1].data(), images[0].size() * sizeof(float)) == 0);
        CHECK(std::memcmp(images[0].data(), images[2].data(), images[0].size() * sizeof(float)) != 0);  // a seed changes it
        CHECK(std::memcmp(images[0].data(), images[3].data(), images[0].size() * sizeof(float)) == 0);
    }
}

// As the path tracer's (tests/test_preview_nonfinite.cpp): a sky of radiance 3e38, the largest a
// loader accepts, overflows BDPT's light samples and the environment's light subpaths to infinity
// on the sphere, while the sky seen through the lens ((0, 2), weight 1) is the sky itself. Every
// sample with a non-finite contribution or weight is counted, and at one sample per pixel exactly
// those pixels have no finite sample and show as NaN, instead of passing for black or dark.
TEST_CASE("BDPT: non-finite contributions are counted and left out of the image", "[render][bdpt][nonfinite]") {
    lab::render::RenderInput input =
        render_input(std::nullopt, "constant:3e38,3e38,3e38", 16, lab::render::LightSampling::mis, 0, kWhiteSphereScene);
    input.settings.integrator = lab::render::Integrator::bdpt;
    input.settings.max_depth = 4;
    lab::render::HostRenderer renderer(input, 1);
    RenderResult r = render_samples(renderer, 1);
    INFO(r.stats.nonfinite_samples << " non-finite samples of " << r.stats.paths);
    CHECK(r.stats.nonfinite_samples > 0);
    CHECK(r.stats.nonfinite_samples < r.stats.paths);
    CHECK(lab::film::image_stats(r.image).non_finite_pixels == r.stats.nonfinite_samples);
}
