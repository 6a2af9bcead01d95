// `bench breakdown`'s "environment twice" build (kernels/bench_standins.h, -DBENCH_TWICE_ENVIRONMENT)
// evaluates every environment sample and pdf a second time and adds it times 0: its figure is the
// environment's share of the time only if it traces the default build's very paths, with the same
// result. Checked on the film bits of a sphere under courtyard.exr.
#include <catch2/catch.hpp>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"

TEST_CASE("Bench: the environment-twice build gives the default build's film bits", "[render][bench][opencl]") {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene("tools/bench_scenes/sphere.json");
    lab::ibl::EnvironmentOptions options;
    options.face_size = 32;
    input.environment = lab::ibl::load_environment("envmaps/courtyard.exr", options);
    input.settings.width = input.settings.height = 16;
    const lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer plain(runtime, input);
    plain.add_samples(2);
    input.settings.extra_build_options += " -DBENCH_TWICE_ENVIRONMENT";
    lab::render::OpenClRenderer twice(runtime, input);
    twice.add_samples(2);
    const lab::render::FilmReadback a = plain.film(), b = twice.film();
    CHECK(plain.statistics().rays == twice.statistics().rays);
    CHECK(a.accumulation == b.accumulation);
    CHECK(a.splat == b.splat);
}
