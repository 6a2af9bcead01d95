// Two estimators of one image compared region by region with Welch's t-test over independent
// renders (validation/region_t_test.hpp): the path tracer's light sampling alone and its MIS with
// BSDF sampling on the Cornell box agree in every region, and at this budget (8 renders of 32
// samples per pixel at 24 x 24, 2 x 2 regions) the test sees a 10 % bias. Over-relaxed sphere
// tracing (the default) gives the image plain sphere tracing gives. The environment's light samples
// give a sphere the image BSDF sampling gives (a density wrong by the row's probability: all 12
// regions rejected).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"
#include "validation/region_t_test.hpp"

namespace {

// `count` renders of `input` with the seeds first_seed, first_seed + 1, ...
std::vector<lab::film::ImageRgb> renders(const lab::opencl::Runtime& runtime, lab::render::RenderInput input, int count, int spp,
                                         uint64_t first_seed) {
    std::vector<lab::film::ImageRgb> out;
    for (int k = 0; k < count; ++k) {
        input.settings.seed = first_seed + uint64_t(k);
        lab::render::OpenClRenderer renderer(runtime, input);
        out.push_back(render_samples(renderer, spp).image);
    }
    return out;
}

// `count` renders of `spp` samples with light sampling `a` (seeds from first_seed) and with `b`
// (seeds from first_seed + 100), returned in *images_a and *images_b.
void renders_of_two(const lab::opencl::Runtime& runtime, lab::render::RenderInput input, lab::render::LightSampling a,
                    lab::render::LightSampling b, int count, int spp, uint64_t first_seed, std::vector<lab::film::ImageRgb>* images_a,
                    std::vector<lab::film::ImageRgb>* images_b) {
    input.settings.light_sampling = a;
    *images_a = renders(runtime, input, count, spp, first_seed);
    input.settings.light_sampling = b;
    *images_b = renders(runtime, input, count, spp, first_seed + 100);
}

// The images times `factor`: a bias a comparison must see.
std::vector<lab::film::ImageRgb> scaled(std::vector<lab::film::ImageRgb> images, float factor) {
    for (lab::film::ImageRgb& image : images)
        for (float& v : image.rgb) v *= factor;
    return images;
}

}  // namespace

TEST_CASE("Region t-test: light sampling and MIS agree on the Cornell box, and a 10 % bias is seen", "[render][welch][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene("scenes/cornell_box.json");
    input.settings.width = input.settings.height = 24;
    std::vector<lab::film::ImageRgb> lights, mis;
    renders_of_two(runtime, input, lab::render::LightSampling::lights, lab::render::LightSampling::mis, 8, 32, 100, &lights, &mis);
    lab::validation::RegionComparison same = lab::validation::compare_by_region(lights, mis, 2, 2, 0.01);
    const lab::validation::RegionTest* w = same.worst();
    const double detectable = lab::validation::detectable_difference(same);
    std::printf("region t-test, Cornell box, lights vs mis: %d of %zu rejected at %.2g; worst p %.3g (t %.2f, dof %.1f); "
                "detectable bias up to %.1f %%\n",
                same.rejected, same.regions.size(), same.level, w->result.p_value, w->result.t, w->result.dof, 100.0 * detectable);
    CHECK(same.rejected == 0);

    // The same renders with MIS's image 10 % brighter: a bias the test must find at this budget.
    lab::validation::RegionComparison shifted = lab::validation::compare_by_region(lights, scaled(mis, 1.10f), 2, 2, 0.01);
    std::printf("region t-test, Cornell box, lights vs mis x 1.10: %d of %zu rejected\n", shifted.rejected, shifted.regions.size());
    CHECK(shifted.rejected > 0);
}

TEST_CASE("Region t-test: over-relaxed sphere tracing gives the image plain sphere tracing gives", "[render][welch][opencl]") {
    lab::opencl::Runtime runtime("");
    // the test model under a sky, and the scene of thin repeated capsules where a step too far would
    // show as missed or holed surfaces
    for (const char* file : {"scenes/shader_ball.json", "scenes/repetition.json"}) {
        lab::render::RenderInput input;
        input.scene = lab::scene::load_scene(file);
        input.environment = lab::ibl::Environment::constant(brdf::float3(1.0f), "white", lab::ibl::EnvironmentOptions{});
        input.settings.width = input.settings.height = 24;
        input.settings.over_relaxation = 1.0f;
        std::vector<lab::film::ImageRgb> plain = renders(runtime, input, 6, 16, 300);
        input.settings.over_relaxation = 1.5f;
        std::vector<lab::film::ImageRgb> relaxed = renders(runtime, input, 6, 16, 400);
        lab::validation::RegionComparison c = lab::validation::compare_by_region(plain, relaxed, 3, 3, 0.01);
        std::printf("region t-test, %s, over-relaxation 1 vs 1.5: %d of %zu rejected; worst p %.3g\n", file, c.rejected, c.regions.size(),
                    c.worst()->result.p_value);
        INFO(file);
        CHECK(c.rejected == 0);
    }
}

TEST_CASE("Region t-test: the environment's light samples give the image BSDF sampling gives, and a 5 % bias is seen",
          "[render][welch][opencl]") {
    // A Lambert sphere under courtyard.exr: next-event estimation alone draws every light sample from
    // the environment's alias tables and divides by their density, BSDF sampling never reads them,
    // so a wrong probability anywhere on the map would show as a difference of the two images. (Under
    // a map with a small sun, sunset.exr, BSDF sampling's rare huge values break the t-test's normal
    // approximation: one region of 12 is rejected there, although the light-sampled images of the
    // alias tables and of a cdf sampler agree within their noise at 8192 samples per pixel.)
    lab::opencl::Runtime runtime("");
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene("tools/bench_scenes/sphere.json");
    input.environment = lab::ibl::load_environment("envmaps/courtyard.exr", lab::ibl::EnvironmentOptions{});
    input.settings.width = input.settings.height = 24;
    std::vector<lab::film::ImageRgb> lights, bsdf;
    renders_of_two(runtime, input, lab::render::LightSampling::lights, lab::render::LightSampling::bsdf, 12, 128, 500, &lights, &bsdf);
    lab::validation::RegionComparison same = lab::validation::compare_by_region(lights, bsdf, 2, 2, 0.01);
    const double detectable = lab::validation::detectable_difference(same);
    std::printf("region t-test, sphere under courtyard, lights vs bsdf: %d of %zu rejected; worst p %.3g; detectable bias up to %.1f %%\n",
                same.rejected, same.regions.size(), same.worst()->result.p_value, 100.0 * detectable);
    CHECK(same.rejected == 0);
    lab::validation::RegionComparison shifted = lab::validation::compare_by_region(scaled(lights, 1.05f), bsdf, 2, 2, 0.01);
    std::printf("region t-test, sphere under courtyard, lights x 1.05 vs bsdf: %d of %zu rejected\n", shifted.rejected,
                shifted.regions.size());
    CHECK(shifted.rejected > 0);
}
