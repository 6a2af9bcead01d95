// Launches over part of the image (Renderer::set_launch_pixels), which the viewer uses so that an
// edit waits at most one short launch: a pass split into launches adds exactly the samples one
// whole-image launch adds, for every integrator and on both devices, and while a pass is in
// progress each pixel is resolved over its own sample count (and the splats over every light path
// traced so far).
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "common/read_text_file.hpp"
#include "opencl/runtime.hpp"
#include "render/film_resolve.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

using lab::render::Integrator;
using lab::render::LightSampling;

// The test model under a constant environment; for the light tracer, which refuses an environment,
// the Cornell box with its sphere light.
lab::render::RenderInput model(Integrator integrator, int size) {
    lab::render::RenderInput input = integrator == Integrator::lt
                                         ? render_input(std::nullopt, "", size, LightSampling::mis, 11, lab::read_text_file("scenes/cornell_box.json", 1 << 20, "scene"))
                                         : render_input(std::nullopt, "constant:1,1,1", size, LightSampling::mis, 11);
    input.settings.integrator = integrator;
    return input;
}

// The number of float words that differ by more than `relative` (0: bit for bit).
size_t differing(const std::vector<float>& a, const std::vector<float>& b, float relative) {
    REQUIRE(a.size() == b.size());
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        if (relative == 0.0f ? a[i] != b[i] : !(std::fabs(a[i] - b[i]) <= relative * std::max(std::fabs(a[i]), std::fabs(b[i])) + 1e-30f)) ++n;
    return n;
}

// Renders `spp` samples in launches of about `launch_pixels` pixels (0: whole image), one launch per
// call, so that every pass is split the way the viewer splits it.
void render_split(lab::render::Renderer& r, int spp, int launch_pixels) {
    r.set_launch_pixels(launch_pixels);
    while (r.samples_per_pixel() < spp) r.add_samples(spp - r.samples_per_pixel(), 0.0);
}

}  // namespace

TEST_CASE("resolve_film: a pass in progress counts its samples on the pixels it reached, and its light paths in the splat scale",
          "[render][film]") {
    lab::render::FilmReadback film;
    // 4 pixels, 2 samples on every one, and a third on the first 2 (the pass in progress); pixel 3
    // had one non-finite sample.
    film.accumulation = {3, 3, 3, 0, 6, 6, 6, 0, 2, 2, 2, 0, 1, 1, 1, 1};
    film.splat = {1.25f, 1.25f, 1.25f, 0, 0, 0, 2.5f, 2.5f, 2.5f, 0, 0, 0};
    lab::film::ImageRgb image = lab::render::resolve_film(film, 2, 4, 1, lab::render::PartialPass{2, 1});
    // light paths per pixel: 2 + 1 * 2 / 4 = 2.5
    CHECK(image.at(0, 0)[0] == Approx(3.0 / 3.0 + 1.25 / 2.5));
    CHECK(image.at(1, 0)[0] == Approx(6.0 / 3.0));
    CHECK(image.at(2, 0)[0] == Approx(2.0 / 2.0 + 2.5 / 2.5));
    CHECK(image.at(3, 0)[0] == Approx(1.0 / 1.0));
    // Before the first complete pass, a pixel the pass has not reached has no sample: 0.
    lab::film::ImageRgb first = lab::render::resolve_film(film, 0, 4, 1, lab::render::PartialPass{2, 1});
    CHECK(first.at(3, 0)[0] == 0.0f);
    CHECK_THROWS_AS(lab::render::resolve_film(film, 2, 4, 1, lab::render::PartialPass{5, 1}), std::invalid_argument);
}

TEST_CASE("Renderer: a pass split into launches of part of the image adds the same samples, and resolves each pixel by its own count",
          "[render][interface]") {
    const int size = 16;  // 256 pixels: launches of 100 pixels round up to 128, two per pass
    lab::render::HostRenderer whole(model(Integrator::pt, size), 2);
    whole.add_samples(1);
    const lab::film::ImageRgb one = whole.image();
    whole.add_samples(1);
    const lab::film::ImageRgb two = whole.image();

    lab::render::HostRenderer split(model(Integrator::pt, size), 2);
    split.set_launch_pixels(100);
    CHECK(split.add_samples(2, 0.0) == 0);  // one launch: half a pass, no complete sample yet
    CHECK(split.pass_pixels() == 128);
    CHECK(split.samples_per_pixel() == 0);
    CHECK_THROWS_AS(split.film(), std::logic_error);  // the film cannot be saved in the middle of a pass
    lab::film::ImageRgb half = split.image();
    CHECK(std::equal(half.rgb.begin(), half.rgb.begin() + 3 * 128, one.rgb.begin()));
    CHECK(std::all_of(half.rgb.begin() + 3 * 128, half.rgb.end(), [](float v) { return v == 0.0f; }));
    CHECK(split.add_samples(2, 0.0) == 1);  // the second half completes the pass
    CHECK(split.image().rgb == one.rgb);
    CHECK(split.add_samples(1, 0.0) == 0);  // half of the second pass: 2 samples on its pixels, 1 on the others
    half = split.image();
    CHECK(std::equal(half.rgb.begin(), half.rgb.begin() + 3 * 128, two.rgb.begin()));
    CHECK(std::equal(half.rgb.begin() + 3 * 128, half.rgb.end(), one.rgb.begin() + 3 * 128));
    CHECK(split.statistics().paths == uint64_t(256 + 128));
    split.add_samples(1, 0.0);
    CHECK(split.image().rgb == two.rgb);
    CHECK(split.sample_ranges().count() == 2);
    CHECK(differing(split.film().accumulation, whole.film().accumulation, 0.0f) == 0);
    CHECK(differing(split.film().squares, whole.film().squares, 0.0f) == 0);
    // A reset drops the pass in progress with the rest.
    split.add_samples(1, 0.0);
    split.reset();
    CHECK(split.pass_pixels() == 0);
    CHECK(split.samples_per_pixel() == 0);
}

TEST_CASE("Renderer: light tracing's splats split into launches are the whole-image launch's (host, one thread)", "[render][interface][bdpt]") {
    lab::render::HostRenderer whole(model(Integrator::lt, 12), 1), split(model(Integrator::lt, 12), 1);
    render_split(whole, 2, 0);
    render_split(split, 2, 50);
    // One thread runs the pixels in the same order either way, so the splats land in the same order.
    CHECK(differing(split.film().splat, whole.film().splat, 0.0f) == 0);
    CHECK(split.image().rgb == whole.image().rgb);
}

TEST_CASE("OpenCL renderer: launches offset into the image add the whole-image launch's samples (pt bit for bit, lt to rounding)",
          "[render][interface][opencl]") {
    lab::opencl::Runtime runtime("");
    for (Integrator integrator : {Integrator::pt, Integrator::lt}) {
        INFO(lab::render::integrator_name(integrator));
        lab::render::OpenClRenderer whole(runtime, model(integrator, 24)), split(runtime, model(integrator, 24));
        render_split(whole, 2, 0);
        render_split(split, 2, 130);  // 576 pixels in launches of 192: offsets 0, 192, 384
        CHECK(differing(split.film().accumulation, whole.film().accumulation, 0.0f) == 0);
        // Concurrent splats land in the scheduler's order: equal to float rounding of a few dozen
        // additions; lt's squares are of its splats per pass (render::add_pass_squares), twice that.
        CHECK(differing(split.film().squares, whole.film().squares, integrator == Integrator::lt ? 2e-5f : 0.0f) == 0);
        CHECK(differing(split.film().splat, whole.film().splat, 1e-5f) == 0);
    }
}
