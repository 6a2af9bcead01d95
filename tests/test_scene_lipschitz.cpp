// The Lipschitz analysis (scene/lipschitz.hpp) against a numerical estimate: the largest slope
// |f(p) - f(q)| / |p - q| over random close pairs never exceeds a scene's declared bound (+1e-3 for
// float rounding), and the estimator is sharp enough to see a bound above 1 where there is one.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "scene/compile.hpp"
#include "scene/interpreter.hpp"
#include "scene/lipschitz.hpp"
#include "scene/load_scene.hpp"
#include "scene/source_literals.hpp"
#include "sdf/sdf.hpp"
#include "test_scene_points.hpp"

using lab::scene::Scene;
using lab::scene::Vec3;

namespace {

// Pairs 1e-2 apart: far enough that float rounding of f (|f| < 20, a few ulps of 2e-6) moves a
// slope by less than 1e-3, close enough to resolve the blends.
double estimate_lipschitz(const Scene& scene, size_t pairs, uint64_t seed) {
    const float h = 1e-2f;
    lab::validation::UniformRandom rng(seed);
    double worst = 0.0;
    for (const Vec3& p : scene_test::random_points(pairs, seed)) {
        Vec3 q = p + h * scene_test::random_direction(rng);
        double distance = glm::length(glm::dvec3(q) - glm::dvec3(p));
        double slope = std::fabs(double(lab::scene::scene_distance(scene, p)) - double(lab::scene::scene_distance(scene, q))) / distance;
        worst = std::fmax(worst, slope);
    }
    return worst;
}

bool has_warning(const lab::scene::CompiledScene& c, const std::string& text) {
    for (const std::string& w : c.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("scene lipschitz: the numerical estimate stays within every scene's declared bound", "[scene]") {
    for (const std::string& file : scene_test::all_scene_files()) {
        Scene scene = lab::scene::load_scene(file);
        lab::scene::SceneAnalysis a = lab::scene::analyse_scene(scene);
        if (!a.is_distance_bound) continue;  // tests/scene_data/asymmetric_repeat.json: next test case
        double estimate = estimate_lipschitz(scene, 60000, 31);
        std::printf("scene Lipschitz: %-40s declared %.6g, estimated %.6g\n", file.c_str(), a.lipschitz, estimate);
        INFO(file << ": declared " << a.lipschitz << ", estimated " << estimate);
        CHECK(estimate <= a.lipschitz + 1e-3);
        if (file.rfind("scenes/", 0) == 0) {
            // The scenes shipped are all 1-Lipschitz, and the estimate comes close to that (the
            // exact distances of the ground and the primitives have slope 1 along the gradient).
            CHECK(a.lipschitz == 1.0f);
            CHECK(estimate > 0.99);
        }
    }
}

TEST_CASE("scene lipschitz: the shader ball is 1-Lipschitz - a displaced scene declares more and says so", "[scene]") {
    lab::scene::CompiledScene ball = lab::scene::compile_scene(lab::scene::load_scene("scenes/shader_ball.json"));
    CHECK(ball.lipschitz == 1.0f);
    CHECK(ball.is_distance_bound);
    CHECK(ball.warnings.empty());
    CHECK(ball.source.find("#define SCENE_LIPSCHITZ 1.0f\n") != std::string::npos);

    Scene displaced = lab::scene::load_scene("tests/scene_data/displaced.json");
    lab::scene::CompiledScene c = lab::scene::compile_scene(displaced);
    const float expected = sdf::lipschitz_displace_sine(1.0f, 0.08f, 8.0f);  // 1 + A w = 1.64
    CHECK(c.lipschitz == expected);
    CHECK(c.lipschitz > 1.6f);
    CHECK(c.source.find("#define SCENE_LIPSCHITZ " + lab::scene::float_literal(expected) + "\n") != std::string::npos);
    CHECK(has_warning(c, "tests/scene_data/displaced.json: the distance field's Lipschitz bound is 1.64 (object \"bumpy\"), above 1"));
    // The estimator does see the steeper field: this case can fail.
    double estimate = estimate_lipschitz(displaced, 60000, 7);
    CHECK(estimate > 1.3);
    CHECK(estimate <= c.lipschitz + 1e-3);
}

TEST_CASE("scene lipschitz: combinator bounds and repetition conditions", "[scene]") {
    // Round and chamfer blends of exact fields: sqrt 2 (sdf/lipschitz.h).
    lab::scene::SceneAnalysis combinators = lab::scene::analyse_scene(lab::scene::load_scene("tests/scene_data/combinators.json"));
    CHECK(combinators.lipschitz == sdf::lipschitz_round(1.0f, 1.0f));
    CHECK(combinators.is_distance_bound);

    // An off-centre child: the field jumps at the cell faces, which the analysis reports and the
    // estimator confirms (slopes of order jump / 1e-2).
    Scene asymmetric = lab::scene::load_scene("tests/scene_data/asymmetric_repeat.json");
    lab::scene::CompiledScene c = lab::scene::compile_scene(asymmetric);
    CHECK_FALSE(c.is_distance_bound);
    REQUIRE(c.warnings.size() == 1);
    CHECK(c.warnings[0] ==
          "tests/scene_data/asymmetric_repeat.json: objects[0].shape: the child is not mirror-symmetric about its cell's mid-plane x = 0: "
          "the field jumps at the cell faces (a neighbouring copy can be nearer); the field is not a distance bound and rays may step "
          "through surfaces");
    CHECK(estimate_lipschitz(asymmetric, 20000, 3) > 10.0);

    // A child that does not fit its cell, and per-node figures.
    auto node = [](const std::string& shape) {
        std::string text = R"({"camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0]},
                               "materials": {"m": {}}, "objects": [{"name": "o", "material": "m", "shape": )" +
                           shape + "}]}";
        return lab::scene::analyse_shape(lab::scene::parse_scene(text, "t.json").objects[0].shape);
    };
    lab::scene::ShapeAnalysis too_big = node(R"({"type": "repeat", "period": [1, 0, 0], "child": {"type": "sphere", "radius": 0.6}})");
    REQUIRE(too_big.broken.size() == 1);
    CHECK(too_big.broken[0] ==
          "objects[0].shape: the child (extent 0.6 along x) does not fit in its cell (half the period is 0.5): the copies are cut at the cell faces");
    // Translating along an unrepeated axis keeps the bound; a quarter turn keeps the symmetry.
    CHECK(node(R"({"type": "repeat", "period": [1, 0, 1], "child": {"type": "translate", "offset": [0, 3, 0],
                   "child": {"type": "rotate", "axis": [0, 1, 0], "degrees": 90, "child": {"type": "box", "half_size": [0.2, 1, 0.4]}}}})")
              .broken.empty());
    // A 0.2 x 0.4 footprint turned by 45 degrees about y is symmetric about neither x = 0 nor
    // z = 0 (the mirror swaps its two axes): both repeated axes are reported.
    CHECK(node(R"({"type": "repeat", "period": [2, 0, 2], "child": {"type": "rotate", "axis": [0, 1, 0], "degrees": 45,
                   "child": {"type": "box", "half_size": [0.2, 0.2, 0.4]}}})")
              .broken.size() == 2);
    lab::scene::ShapeAnalysis limited = node(R"({"type": "repeat_limited", "period": [1, 0, 1], "count_min": [-2, 0, 0], "count_max": [2, 0, 3],
                                                 "child": {"type": "sphere", "radius": 0.25}})");
    CHECK(limited.broken.empty());
    CHECK(limited.extent == Vec3(2.25f, 0.25f, 3.25f));
    CHECK(limited.mirror_symmetric == std::array<bool, 3>{true, true, false});  // z copies 0..3 are not centred
    lab::scene::ShapeAnalysis smooth = node(R"({"type": "smooth_union", "radius": 0.4, "children": [{"type": "sphere", "radius": 1},
                                                {"type": "translate", "offset": [1, 0, 0], "child": {"type": "sphere", "radius": 1}}]})");
    CHECK(smooth.lipschitz == 1.0f);
    CHECK(smooth.extent == Vec3(2.1f, 1.1f, 1.1f));
    CHECK(node(R"({"type": "chamfer_subtraction", "radius": 0.1, "children": [{"type": "sphere", "radius": 1}, {"type": "sphere", "radius": 0.5}]})")
              .lipschitz == sdf::lipschitz_chamfer(1.0f, 1.0f));
    CHECK(node(R"({"type": "scale", "factor": 3, "child": {"type": "displace", "amplitude": 0.1, "frequency": 5, "child": {"type": "sphere", "radius": 1}}})")
              .lipschitz == sdf::lipschitz_displace_sine(1.0f, 0.1f, 5.0f));
}
