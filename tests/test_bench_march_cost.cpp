// The march-work counters (bench/march_cost.hpp, the generated scene's SCENE_COUNT_EVALUATIONS
// build): the counting build traces the default build's paths (same film bits), and its count of
// distance functions per march step is exact where it is known without the counter: 1 for a scene
// of one object, every object for a plain field (object bounds off); and the test model's box test
// skips its body somewhere.
#include <catch2/catch.hpp>

#include "bench/march_cost.hpp"
#include "opencl/runtime.hpp"
#include "scene/load_scene.hpp"

namespace {

// march_everything: the plain primitives marched too (--geometry march), so that the counters see
// the field of every object; otherwise they are intersected exactly and march nothing.
lab::bench::MarchCost work_of(const lab::opencl::Runtime& runtime, const char* file, bool object_bounds, bool march_everything = true) {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene(file);
    input.environment = lab::ibl::Environment::constant(brdf::float3(0.5f), "grey", lab::ibl::EnvironmentOptions{});
    input.settings.width = input.settings.height = 16;
    input.settings.object_bounds = object_bounds;
    input.settings.march_everything = march_everything;
    return lab::bench::measure_march_cost(runtime, input, 1);
}

}  // namespace

TEST_CASE("March work: the counting build traces the same paths and counts every distance function", "[render][march-work][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::bench::MarchCost one = work_of(runtime, "tools/bench_scenes/sphere.json", true);
    CHECK(one.same_film);
    CHECK(one.rays_per_path > 1.0);
    CHECK(one.steps_per_ray > 1.0);
    CHECK(one.evaluations_per_step == 1.0);

    // scenes/primitives.json: 8 objects, no emitter
    lab::bench::MarchCost plain = work_of(runtime, "scenes/primitives.json", false);
    CHECK(plain.same_film);
    CHECK(plain.evaluations_per_step == 8.0);

    // scenes/shader_ball.json: the body (large, with a box test of its own), the core and the ground.
    // The body's test comes after the other two, so it can skip; tested first, against an infinite
    // nearest distance, it never skipped: exactly 3 per step
    lab::bench::MarchCost ball = work_of(runtime, "scenes/shader_ball.json", true);
    CHECK(ball.same_film);
    CHECK(ball.evaluations_per_step < 3.0);

    // intersected exactly, the sphere is never marched
    lab::bench::MarchCost exact = work_of(runtime, "tools/bench_scenes/sphere.json", true, false);
    CHECK(exact.same_film);
    CHECK(exact.rays_per_path > 1.0);
    CHECK(exact.steps_per_ray == 0.0);
}
