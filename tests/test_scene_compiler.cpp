// The scene compiler (scene/compile.hpp): a scene's kernel source holds only the sdf/ code it uses,
// the defines the renderer reads, floats that read back exactly; material overrides and disabled
// objects change what is compiled and what the host interpreter evaluates alike.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "kernels/host/scene_kernel_source.hpp"
#include "scene/compile.hpp"
#include "scene/interpreter.hpp"
#include "scene/load_scene.hpp"
#include "scene/source_literals.hpp"
#include "test_scene_points.hpp"

using lab::scene::CompiledScene;
using lab::scene::Scene;
using lab::scene::Vec3;

namespace {

const char* const kSphereOnly = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "materials": {"white": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "white", "shape": {"type": "sphere", "radius": 1}}]
})";

std::set<std::string> origin_files(const lab::opencl::AssembledSource& source) {
    std::set<std::string> files;
    for (const auto& o : source.origin) files.insert(o.file);
    return files;
}

std::string error_of(const Scene& scene, const lab::scene::CompileOptions& options) {
    try {
        lab::scene::compile_scene(scene, options);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("scene compiler: a sphere-only scene's kernel holds no other sdf code", "[scene]") {
    CompiledScene c = lab::scene::compile_scene(lab::scene::parse_scene(kSphereOnly, "sphere.json"));
    lab::opencl::AssembledSource source = lab::kernels::assemble_scene_kernel("kernels/scene_probe.cl", c);
    // the sphere is intersected exactly (sdf/exact/), and its field kept for normals and materials
    CHECK(origin_files(source) == std::set<std::string>{"kernels/scene_probe.cl", "scene/generated.h", "single_source/vocabulary.h", "sdf/primitives/sphere.h",
                                                        "sdf/exact/sphere.h", "sdf/exact/interval.h"});
    CHECK(source.text.find("fSphere_xyz(px, py, pz, 1.0f)") != std::string::npos);
    for (const char* absent : {"fTorus", "fBox", "fRoundBox", "fCylinder", "fCapsule", "fCone", "fPlane", "pMod3", "pModInterval3", "fOpUnion",
                               "fOpIntersection", "fOpSubtraction", "fOpDisplaceSine", "lipschitz_"}) {
        INFO(absent);
        CHECK(source.text.find(absent) == std::string::npos);
    }
    // The contract's defines in the geometry, and the BRDF features of a white Lambert material only
    // apart from it (scene/materials.h), where the scene probe, which shades nothing, does not look.
    for (const char* line : {"#define SCENE_LIPSCHITZ 1.0f\n", "#define SCENE_EMITTER_COUNT 0\n", "SS_FN float scene_distance(float3 p)",
                             "SS_FN float scene_distance_material(float3 p, int* material)", "SS_FN int scene_analytic_normal(float3 p, float3* n)",
                             "SS_FN float3 scene_object_0_normal(float3 p)"}) {
        INFO(line);
        CHECK(c.source.find(line) != std::string::npos);
    }
    for (const char* line : {"#define SCENE_MATERIAL_COUNT 1\n", "#define BRDF_FEATURE_DIFFUSE 1\n", "#define BRDF_FEATURE_GLOSSY 0\n",
                             "#define BRDF_FEATURE_TRANSMISSION 0\n"}) {
        INFO(line);
        CHECK(c.material_source.find(line) != std::string::npos);
        CHECK(c.source.find(line) == std::string::npos);
    }
    CHECK(c.material_names == std::vector<std::string>{"white"});
    // The render kernels see those switches: a white Lambert scene's has no microfacet code.
    for (const char* kernel : {"kernels/path_tracer.cl", "kernels/bdpt.cl"}) {
        INFO(kernel);
        std::string text = lab::kernels::assemble_scene_kernel(kernel, c).text;
        CHECK(text.find("lambert") != std::string::npos);
        CHECK(text.find("ggx_d(") == std::string::npos);
        CHECK(text.find("hyper_cauchy_d(") == std::string::npos);
    }
}

TEST_CASE("scene compiler: the shader ball includes exactly the headers it uses", "[scene]") {
    CompiledScene c = lab::scene::compile_scene(lab::scene::load_scene("scenes/shader_ball.json"));
    std::set<std::string> included;
    for (size_t at = c.source.find("#include \"sdf/"); at != std::string::npos; at = c.source.find("#include \"sdf/", at + 1))
        included.insert(c.source.substr(at + 10, c.source.find('"', at + 10) - at - 10));
    // the core (a sphere) and the ground (a plane) are intersected exactly, the body is marched
    CHECK(included == std::set<std::string>{"sdf/primitives/sphere.h", "sdf/primitives/plane.h", "sdf/primitives/box.h",
                                            "sdf/primitives/round_box.h", "sdf/primitives/torus.h", "sdf/primitives/cylinder.h",
                                            "sdf/combinators/union_smooth.h", "sdf/combinators/subtraction.h",
                                            "sdf/combinators/intersection.h", "sdf/exact/interval.h", "sdf/exact/sphere.h",
                                            "sdf/exact/plane.h"});
    // ... and what those pull in is no more than their own helpers.
    std::set<std::string> assembled = origin_files(lab::kernels::assemble_scene_kernel("kernels/scene_probe.cl", c));
    for (const char* unused : {"sdf/primitives/cone.h", "sdf/primitives/capsule.h", "sdf/domain/mod3.h", "sdf/domain/mod_interval3.h",
                               "sdf/combinators/union.h", "sdf/combinators/union_round.h", "sdf/combinators/union_chamfer.h",
                               "sdf/combinators/displace_sine.h", "sdf/lipschitz.h", "sdf/march.h", "sdf/normals.h"}) {
        INFO(unused);
        CHECK(assembled.count(unused) == 0);
    }
    // The body is a combination (tetrahedral normals); the core and the ground have analytic ones.
    CHECK(c.source.find("scene_object_0_normal") == std::string::npos);
    CHECK(c.source.find("SS_FN float3 scene_object_1_normal") != std::string::npos);
    CHECK(c.source.find("SS_FN float3 scene_object_2_normal") != std::string::npos);
    CHECK(c.material_names == std::vector<std::string>{"sample", "ground"});
    CHECK(c.camera.fov_degrees == 36.0f);
    CHECK_FALSE(c.environment.has_value());
}

TEST_CASE("scene compiler: float literals read back exactly", "[scene]") {
    CHECK(lab::scene::float_literal(1.0f) == "1.0f");
    CHECK(lab::scene::float_literal(-2.0f) == "-2.0f");
    CHECK(lab::scene::float_literal(0.5f) == "0.5f");
    CHECK(lab::scene::float_literal(0.1f) == "0.100000001f");
    CHECK(lab::scene::float_literal(1e10f) == "1.0e+10f");
    CHECK(lab::scene::float_literal(1.5e-7f) == "1.50000005e-07f");
    lab::validation::UniformRandom rng(5);
    for (int i = 0; i < 20000; ++i) {
        uint32_t bits = uint32_t(rng.next_bits());
        float v;
        std::memcpy(&v, &bits, sizeof(v));
        if (!std::isfinite(v)) continue;
        std::string literal = lab::scene::float_literal(v);
        INFO(literal);
        REQUIRE(literal.back() == 'f');
        REQUIRE(literal.find('.') != std::string::npos);
        REQUIRE(std::strtof(literal.c_str(), nullptr) == v);
    }
}

TEST_CASE("scene compiler: material overrides and disabled objects", "[scene]") {
    Scene ball = lab::scene::load_scene("scenes/shader_ball.json");
    brdf::Material gold = brdf::load_preset("presets/gold.json").material;

    lab::scene::CompileOptions replace;
    replace.material_overrides["sample"] = gold;
    CompiledScene c = lab::scene::compile_scene(ball, replace);
    CHECK(std::memcmp(&c.materials[0], &gold, sizeof(gold)) == 0);
    CHECK(c.materials[1].weight_diffuse == 1.0f);  // the ground's stays
    // Gold needs glossy reflection, the default glossy plastic and the ground need diffuse.
    CHECK(c.material_source.find("#define BRDF_FEATURE_GLOSSY 1\n") != std::string::npos);
    lab::scene::CompileOptions grey_only;
    grey_only.material_overrides["sample"] = ball.materials[1].material;
    CompiledScene grey = lab::scene::compile_scene(ball, grey_only);
    CHECK(grey.material_source.find("#define BRDF_FEATURE_GLOSSY 0\n") != std::string::npos);
    // The geometry is the same whatever the materials, and so is every program that only marches
    // (the packet kernels): the renderer keeps it, and a cold PoCL cache compiles it once.
    CHECK(grey.source == c.source);
    CHECK(lab::kernels::assemble_scene_kernel("kernels/march_packets.cl", grey).text ==
          lab::kernels::assemble_scene_kernel("kernels/march_packets.cl", c).text);
    CHECK(lab::kernels::assemble_scene_kernel("kernels/path_tracer.cl", grey).text !=
          lab::kernels::assemble_scene_kernel("kernels/path_tracer.cl", c).text);

    lab::scene::CompileOptions no_ground;
    no_ground.disabled_objects = {"ground"};
    CompiledScene without = lab::scene::compile_scene(ball, no_ground);
    CHECK(without.source.find("scene_object_1(") != std::string::npos);
    CHECK(without.source.find("scene_object_2") == std::string::npos);
    CHECK(without.material_names.size() == 2);  // slots stay numbered as declared
    Scene interpreted = lab::scene::apply_options(ball, no_ground);
    CHECK(lab::scene::scene_distance(ball, Vec3(3.0f, 0.5f, 3.0f)) == 0.5f);  // the ground is nearest
    CHECK(lab::scene::scene_distance(interpreted, Vec3(3.0f, 0.5f, 3.0f)) > 2.0f);
    int ground_hits = 0;
    for (const Vec3& p : scene_test::random_points(2000, 11)) {
        int material;
        lab::scene::scene_distance_material(interpreted, p, &material);
        ground_hits += material == 1;
    }
    CHECK(ground_hits == 0);

    lab::scene::CompileOptions unknown_material;
    unknown_material.material_overrides["nope"] = gold;
    CHECK(error_of(ball, unknown_material) ==
          "scenes/shader_ball.json: materials: no material named \"nope\" to replace (declared: sample, ground)");
    lab::scene::CompileOptions unknown_object;
    unknown_object.disabled_objects = {"floor"};
    CHECK(error_of(ball, unknown_object) ==
          "scenes/shader_ball.json: objects: no object named \"floor\" to disable (objects: body, core, ground)");
    lab::scene::CompileOptions everything;
    everything.disabled_objects = {"body", "core", "ground"};
    CHECK(error_of(ball, everything) == "scenes/shader_ball.json: objects: nothing is left to render once the disabled objects are left out");
}

TEST_CASE("scene compiler: emitters get material slots with their radiance", "[scene]") {
    CompiledScene c = lab::scene::compile_scene(lab::scene::load_scene("scenes/metaballs.json"));
    REQUIRE(c.emitters.size() == 1);
    CHECK(c.material_names == std::vector<std::string>{"sample", "accent", "ground", "emitters[0]"});
    CHECK(c.emitters[0].material == 3);
    CHECK(c.emission[3] == Vec3(40.0f, 34.0f, 26.0f));
    CHECK(c.emission[0] == Vec3(0.0f));
    CHECK(c.source.find("#define SCENE_EMITTER_COUNT 1\n") != std::string::npos);
    CHECK(c.material_source.find("#define SCENE_MATERIAL_COUNT 4\n") != std::string::npos);
    // Hitting the emitter returns its slot.
    int material = -1;
    float d = lab::scene::scene_distance_material(lab::scene::load_scene("scenes/metaballs.json"), c.emitters[0].center, &material);
    CHECK(d == -c.emitters[0].radius);
    CHECK(material == 3);
}

TEST_CASE("scene compiler: point lights pass through, a reflecting emitter follows its material's override", "[scene]") {
    const char* text = R"({
      "camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"sample": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
      "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}},
                  {"name": "ground", "material": "sample", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 1}}],
      "emitters": [{"type": "point", "position": [0, 4, 0], "intensity": [1, 1, 1]},
                   {"center": [3, 0, 0], "radius": 0.5, "radiance": [2, 2, 2], "material": "sample"}]
    })";
    const lab::scene::Scene scene = lab::scene::parse_scene(text, "scenes/x.json");
    lab::scene::CompileOptions options;
    brdf::Material gold = brdf::default_material();
    gold.metallic = 1.0f;
    options.material_overrides["sample"] = gold;
    const CompiledScene c = lab::scene::compile_scene(scene, options);
    REQUIRE(c.point_lights.size() == 1);
    CHECK(c.point_lights[0].position == Vec3(0, 4, 0));
    CHECK(c.source.find("#define SCENE_EMITTER_COUNT 1\n") != std::string::npos);  // the point light is no geometry
    REQUIRE(c.materials.size() == 2);
    CHECK(c.materials[1].metallic == 1.0f);  // the emitter's slot scatters with the override
    CHECK(c.emission[1] == Vec3(2.0f));
    // bounds: camera (0, 0, 5), ball [-1, 1]^3, emitter [2.5, 3.5] x [-0.5, 0.5]^2, point (0, 4, 0);
    // the endless plane adds the cube around the camera out to its look-at distance, 5: [-5, 5]^2 x [0, 10]
    CHECK(c.bounds_center == Vec3(0.0f, 0.0f, 4.5f));
    CHECK(c.bounds_radius == Approx(0.5 * std::sqrt(10.0 * 10.0 + 10.0 * 10.0 + 11.0 * 11.0)).epsilon(1e-6));
    // without the plane, the box of what is bounded alone
    options.disabled_objects.push_back("ground");
    const CompiledScene bounded = lab::scene::compile_scene(scene, options);
    CHECK(bounded.bounds_center == Vec3(1.25f, 1.5f, 2.0f));
    CHECK(bounded.bounds_radius == Approx(0.5 * std::sqrt(4.5 * 4.5 + 5.0 * 5.0 + 6.0 * 6.0)).epsilon(1e-6));
}
