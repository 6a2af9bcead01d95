// `bench breakdown`'s "environment twice" build (kernels/bench_standins.h, -DBENCH_TWICE_ENVIRONMENT)
// evaluates every environment sample and pdf a second time and adds it times 0: its figure is the
// environment's share of the time only if it traces the default build's very paths, with the same
// result. Checked on the film bits of a sphere under courtyard.exr.
#include <catch2/catch.hpp>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "scene/test_model.hpp"

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

// The BSDF stand-in (-DBENCH_STANDIN_BSDF, a grey Lambert reflector) must replace the calls the path
// tracer makes: until stop 29 it redefined bsdf_eval, bsdf_pdf and bsdf_sample, which the path
// tracer no longer calls (it calls the *_clamped forms), so its build rendered the default build's
// very film and `bench breakdown` read noise as the BSDF's share. On the test model, whose
// materials are not grey Lambert, its film must differ; that old stand-in fails this check.
TEST_CASE("Bench: the BSDF stand-in build replaces the path tracer's BSDF", "[render][bench][opencl]") {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_test_model();
    lab::ibl::EnvironmentOptions options;
    options.face_size = 32;
    input.environment = lab::ibl::load_environment("envmaps/courtyard.exr", options);
    input.settings.width = input.settings.height = 16;
    const lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer plain(runtime, input);
    plain.add_samples(2);
    input.settings.extra_build_options += " -DBENCH_STANDIN_BSDF";
    lab::render::OpenClRenderer standin(runtime, input);
    standin.add_samples(2);
    CHECK(plain.film().accumulation != standin.film().accumulation);
}
