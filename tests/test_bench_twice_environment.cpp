// `bench breakdown`'s "environment twice" build (bench/kernels/part_standins.h, -DBENCH_TWICE_ENVIRONMENT)
// evaluates every environment sample and pdf a second time and adds it times 0: its figure is the
// environment's share of the time only if it traces the default build's very paths, with the same
// result. Checked on the film bits of a sphere under courtyard.exr.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "bench/part_build.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"
#include "scene/test_model.hpp"

namespace {

// 2 samples of `scene` at 16x16 under courtyard.exr (face 32): the default build, or with `define`, the
// part build that defines it.
struct BenchRender {
    lab::render::FilmReadback film;
    uint64_t rays = 0;
};
BenchRender render_bench_build(const lab::scene::Scene& scene, const std::string& define) {
    lab::render::RenderInput input;
    input.scene = scene;
    lab::ibl::EnvironmentOptions environment;
    environment.face_size = 32;
    input.environment = lab::ibl::load_environment("envmaps/courtyard.exr", environment);
    input.settings.width = input.settings.height = 16;
    if (!define.empty()) lab::bench::use_part_build(input.settings.opencl, define);
    const lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer renderer(runtime, input);
    renderer.add_samples(2);
    return BenchRender{renderer.film(), renderer.statistics().rays};
}

}  // namespace

TEST_CASE("Bench: the environment-twice build gives the default build's film bits", "[render][bench][opencl]") {
    const lab::scene::Scene sphere = lab::scene::load_scene("tools/bench_scenes/sphere.json");
    const BenchRender plain = render_bench_build(sphere, ""), twice = render_bench_build(sphere, "BENCH_TWICE_ENVIRONMENT");
    CHECK(plain.rays == twice.rays);
    CHECK(plain.film.accumulation == twice.film.accumulation);
    CHECK(plain.film.splat == twice.film.splat);
}

// The BSDF stand-in (-DBENCH_STANDIN_BSDF, a grey Lambert reflector) must replace the calls the path
// tracer makes (the *_clamped forms): a stand-in that redefined functions the path tracer does not
// call (bsdf_eval, bsdf_pdf, bsdf_sample) would render the default build's very film, and `bench
// breakdown` would read noise as the BSDF's share. On the test model, whose materials are not grey
// Lambert, its film must differ; such a stand-in fails this check.
TEST_CASE("Bench: the BSDF stand-in build replaces the path tracer's BSDF", "[render][bench][opencl]") {
    const lab::scene::Scene model = lab::scene::load_test_model();
    CHECK(render_bench_build(model, "").film.accumulation != render_bench_build(model, "BENCH_STANDIN_BSDF").film.accumulation);
}
