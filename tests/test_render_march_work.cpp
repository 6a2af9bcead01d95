// The march-work counters (render/march_work.hpp, the generated scene's SCENE_COUNT_EVALUATIONS
// build): the counting build traces the default build's paths (same film bits), and its count of
// distance functions per march step is exact where it is known without the counter: 1 for a scene
// of one object, every object for a plain field (object bounds off); and the test model's box test
// skips its body somewhere.
#include <catch2/catch.hpp>

#include "opencl/runtime.hpp"
#include "render/march_work.hpp"
#include "scene/load_scene.hpp"

namespace {

lab::render::MarchWork work_of(const lab::opencl::Runtime& runtime, const char* file, bool object_bounds) {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene(file);
    input.environment = lab::ibl::Environment::constant(brdf::float3(0.5f), "grey", lab::ibl::EnvironmentOptions{});
    input.settings.width = input.settings.height = 16;
    input.settings.object_bounds = object_bounds;
    return lab::render::count_march_work(runtime, input, 1);
}

}  // namespace

TEST_CASE("March work: the counting build traces the same paths and counts every distance function", "[render][march-work][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::MarchWork one = work_of(runtime, "tools/bench_scenes/sphere.json", true);
    CHECK(one.same_film);
    CHECK(one.rays_per_path > 1.0);
    CHECK(one.steps_per_ray > 1.0);
    CHECK(one.evaluations_per_step == 1.0);

    // scenes/primitives.json: 8 objects, no emitter
    lab::render::MarchWork plain = work_of(runtime, "scenes/primitives.json", false);
    CHECK(plain.same_film);
    CHECK(plain.evaluations_per_step == 8.0);

    // scenes/shader_ball.json: the body (large, with a box test of its own), the core and the ground.
    // The body's test comes after the other two, so it can skip; tested first, against an infinite
    // nearest distance, it never skipped: exactly 3 per step
    lab::render::MarchWork ball = work_of(runtime, "scenes/shader_ball.json", true);
    CHECK(ball.same_film);
    CHECK(ball.evaluations_per_step < 3.0);
}
