// Exact intersection in whole scenes: the OpenCL build of the exact hits and of the rule that
// combines them with the march (sdf/exact/trace.h) against the host build; the packet kernels' lane
// form of the exact hits against the scalar form (checked once by hand: a plane whose lane form adds
// its dot product's terms in the other order differs on 120 of lane_transformed's rays, a first
// crossing that takes exit from outside on 3 to 899 rays of every scene, a cylinder's axis branch
// with the inside test inverted on 117 of the primitives' rays, a cone that takes the wrong root of
// a steep ray on 4 rays of two scenes); the rule's edge cases;
// and two images whose geometry has a closed form: an emissive sphere's projected area and a box
// edge's place.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "kernels/host/scene_kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "render/host_kernels.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"

using lab::scene::Scene;
using lab::scene::Vec3;

namespace {

struct RayHits {
    std::vector<float> exact_t, hit_t;
    std::vector<int> status;
};

RayHits opencl_rays(const lab::opencl::Runtime& runtime, const lab::scene::CompiledScene& scene, const std::vector<float>& rays, float max_distance) {
    lab::opencl::Program program = runtime.build(lab::kernels::assemble_scene_kernel("kernels/scene_ray_probe.cl", scene),
                                                 lab::kernels::kSceneBuildOptions);
    lab::opencl::KernelHandle kernel = program.kernel("scene_ray_probe");
    const size_t n = rays.size() / 6;
    lab::opencl::BufferHandle in = runtime.buffer(rays.size() * sizeof(float), CL_MEM_READ_ONLY);
    lab::opencl::BufferHandle exact_t = runtime.buffer(n * sizeof(float), CL_MEM_WRITE_ONLY);
    lab::opencl::BufferHandle hit_t = runtime.buffer(n * sizeof(float), CL_MEM_WRITE_ONLY);
    lab::opencl::BufferHandle status = runtime.buffer(n * sizeof(int), CL_MEM_WRITE_ONLY);
    runtime.write(in, rays.data(), rays.size() * sizeof(float));
    lab::opencl::set_kernel_args(kernel, int(n), max_distance, in, exact_t, hit_t, status);
    runtime.launch_1d(kernel, n, 64);
    runtime.finish();
    RayHits r{std::vector<float>(n), std::vector<float>(n), std::vector<int>(n)};
    runtime.read(exact_t, r.exact_t.data(), n * sizeof(float));
    runtime.read(hit_t, r.hit_t.data(), n * sizeof(float));
    runtime.read(status, r.status.data(), n * sizeof(int));
    return r;
}

lab::render::host_kernels::MarchResult host_ray(const Scene& scene, Vec3 o, Vec3 v, float max_distance, float over_relaxation = 1.0f) {
    using namespace lab::render::host_kernels;
    const lab::render::HostSceneScope scope(scene);
    MarchSettings s = march_settings_default(1.0f);
    s.max_distance = max_distance;
    s.over_relaxation = over_relaxation;
    return march_scene_ray(o, v, s);
}

// A scene of the edge cases: a camera, one grey material "m" and these objects (JSON).
Scene edge_scene(const std::string& objects, const std::string& name) {
    return lab::scene::parse_scene(R"({"camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0], "fov_degrees": 40},
      "materials": {"m": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}}, "objects": [)" + objects + "]}", name);
}

// Every primitive under rotations, uniform scales and translations (all intersected exactly), and a
// blend of two of them (marched), over a ground plane.
const char* const kTransformedScene = R"({
  "camera": {"type": "pinhole", "position": [0, 3, 9], "look_at": [0, 0.5, 0], "fov_degrees": 40},
  "materials": {"m": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
  "objects": [
    {"name": "ground", "material": "m", "shape": {"type": "plane", "normal": [0.1, 1, 0], "offset": 0.5}},
    {"name": "torus", "material": "m", "shape": {"type": "translate", "offset": [-2, 1, 0], "child": {"type": "rotate", "axis": [1, 0.3, 0], "degrees": 70,
      "child": {"type": "scale", "factor": 1.5, "child": {"type": "torus", "major_radius": 0.6, "minor_radius": 0.2}}}}},
    {"name": "cone", "material": "m", "shape": {"type": "translate", "offset": [0, 0.2, -1], "child": {"type": "rotate", "axis": [0, 0, 1], "degrees": 30,
      "child": {"type": "cone", "radius": 0.5, "height": 1.2}}}},
    {"name": "capsule", "material": "m", "shape": {"type": "translate", "offset": [2, 1, 0], "child": {"type": "rotate", "axis": [1, 1, 0], "degrees": 45,
      "child": {"type": "capsule", "radius": 0.3, "half_height": 0.6}}}},
    {"name": "round_box", "material": "m", "shape": {"type": "translate", "offset": [0, 1.5, 1.5], "child": {"type": "scale", "factor": 0.7,
      "child": {"type": "round_box", "half_size": [0.6, 0.4, 0.5], "radius": 0.15}}}},
    {"name": "cylinder", "material": "m", "shape": {"type": "translate", "offset": [-1, 0.5, 2], "child": {"type": "rotate", "axis": [0, 1, 1], "degrees": 80,
      "child": {"type": "cylinder", "radius": 0.35, "half_height": 0.5}}}},
    {"name": "blend", "material": "m", "shape": {"type": "smooth_union", "radius": 0.3, "children": [
      {"type": "translate", "offset": [1.5, 0.5, 2], "child": {"type": "sphere", "radius": 0.4}},
      {"type": "translate", "offset": [1.5, 0.5, 2.5], "child": {"type": "box", "half_size": [0.3, 0.3, 0.3]}}]}}
  ],
  "emitters": [{"center": [0, 3, 0], "radius": 0.3, "radiance": [5, 5, 5]}]
})";

// The primitives that have a lane form of their exact hit (plane, box, sphere) under rotations,
// uniform scales and translations, an emitter, and a blend (marched).
const char* const kLaneTransformedScene = R"({
  "camera": {"type": "pinhole", "position": [0, 3, 9], "look_at": [0, 0.5, 0], "fov_degrees": 40},
  "materials": {"m": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
  "objects": [
    {"name": "ground", "material": "m", "shape": {"type": "rotate", "axis": [0, 0, 1], "degrees": 5, "child": {"type": "plane", "normal": [0.1, 1, 0.2], "offset": 0.5}}},
    {"name": "box", "material": "m", "shape": {"type": "translate", "offset": [-1.5, 0.5, 0], "child": {"type": "rotate", "axis": [1, 0.3, 0], "degrees": 40,
      "child": {"type": "scale", "factor": 1.3, "child": {"type": "box", "half_size": [0.5, 0.3, 0.4]}}}}},
    {"name": "ball", "material": "m", "shape": {"type": "translate", "offset": [1, 0.6, 0.5], "child": {"type": "scale", "factor": 0.8,
      "child": {"type": "sphere", "radius": 0.7}}}},
    {"name": "blend", "material": "m", "shape": {"type": "smooth_union", "radius": 0.3, "children": [
      {"type": "translate", "offset": [0, 0.5, 2], "child": {"type": "sphere", "radius": 0.4}},
      {"type": "translate", "offset": [0, 0.5, 2.5], "child": {"type": "box", "half_size": [0.3, 0.3, 0.3]}}]}}
  ],
  "emitters": [{"center": [0, 3, 0], "radius": 0.3, "radiance": [5, 5, 5]}]
})";

// 3000 rays (origin, unit direction: 6 floats each): from the camera into its view, and from points
// in and around the objects.
std::vector<float> probe_rays(const Scene& scene, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<float> rays;
    for (int i = 0; i < 3000; ++i) {
        Vec3 o = i % 2 ? scene.camera.position : Vec3(u(rng) * 3.0f, 0.5f + u(rng) * 2.0f, u(rng) * 3.0f);
        Vec3 v = i % 2 ? glm::normalize(scene.camera.look_at - scene.camera.position + Vec3(u(rng), u(rng), u(rng)) * 0.6f * glm::length(scene.camera.look_at - scene.camera.position))
                       : glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.0f, 0.0f, 1e-3f));
        rays.insert(rays.end(), {o.x, o.y, o.z, v.x, v.y, v.z});
    }
    return rays;
}

}  // namespace

TEST_CASE("Exact intersection: the OpenCL build's hits and combined rays agree with the host build's", "[scene][exact][opencl]") {
    lab::opencl::Runtime runtime;
    std::mt19937 rng(3535);
    const float max_distance = 100.0f;
    std::vector<Scene> scenes = {lab::scene::load_scene("scenes/primitives.json"), lab::scene::load_scene("scenes/cornell_box.json"),
                                 lab::scene::load_scene("scenes/shader_ball.json"), lab::scene::parse_scene(kTransformedScene, "transformed.json")};
    for (const Scene& scene : scenes) {
        const std::vector<float> rays = probe_rays(scene, rng);
        const RayHits cl = opencl_rays(runtime, lab::scene::compile_scene(scene), rays, max_distance);
        size_t exact_hits = 0, exact_failures = 0, combined_failures = 0;
        for (size_t i = 0; i < cl.exact_t.size(); ++i) {
            const Vec3 o(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2]), v(rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5]);
            const float exact = lab::scene::scene_exact_hit(scene, o, v, max_distance);
            // the two builds round alike but for the compilers' choices: a few ulps of the scene's size
            const float tolerance = 1e-5f * std::fmax(1.0f, exact);
            if (std::isfinite(exact)) ++exact_hits;
            if (!(std::isinf(exact) && std::isinf(cl.exact_t[i])) && !(std::fabs(exact - cl.exact_t[i]) <= tolerance)) {
                ++exact_failures;
                UNSCOPED_INFO(scene.file << " ray " << i << ": exact hit host " << exact << ", OpenCL " << cl.exact_t[i]);
            }
            const auto host = host_ray(scene, o, v, max_distance);
            if (host.status != cl.status[i] || (host.status == MARCH_HIT && !(std::fabs(host.t - cl.hit_t[i]) <= 1e-4f * std::fmax(1.0f, host.t))))
                ++combined_failures;
        }
        std::printf("exact OpenCL agreement: %-28s %zu rays, %zu exact hits, %zu exact and %zu combined disagreements\n", scene.file.c_str(),
                    cl.exact_t.size(), exact_hits, exact_failures, combined_failures);
        INFO(scene.file);
        CHECK(exact_failures == 0);
        CHECK(exact_hits >= cl.exact_t.size() / 4);
        // a march may flip a branch on a grazing ray (the rounding of the two compilers)
        CHECK(combined_failures <= cl.exact_t.size() / 500);
    }
}

TEST_CASE("Exact intersection: the packet kernels' lane form gives the scalar form's hits to the bit", "[scene][exact][opencl]") {
    // Both forms do the same float operations in the same order (a select where the scalar form
    // branches), in one program built as the packet kernels are: any difference is a bug, not rounding.
    lab::opencl::Runtime runtime;
    std::mt19937 rng(3536);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Scene> scenes = {lab::scene::load_scene("scenes/primitives.json"), lab::scene::load_scene("scenes/cornell_box.json"),
                                 lab::scene::load_scene("scenes/shader_ball.json"), lab::scene::load_scene("scenes/metaballs.json"),
                                 lab::scene::parse_scene(kTransformedScene, "transformed.json"),
                                 lab::scene::parse_scene(kLaneTransformedScene, "lane_transformed.json")};
    for (const Scene& scene : scenes) {
        const std::vector<float> aos = probe_rays(scene, rng);
        const int n = int(aos.size() / 6), stride = (n + 7) / 8 * 8;
        // where the objects are placed (their outermost translation, else the origin)
        std::vector<Vec3> anchors;
        for (const lab::scene::Object& object : scene.objects) {
            const auto* t = std::get_if<lab::scene::Translate>(&object.shape.kind);
            anchors.push_back(t ? t->offset : Vec3(0.0f));
        }
        // seven arrays of `stride` floats; every third ray's t_max short enough to cut some hits off,
        // every fifth ray along an axis (the branches of rays parallel to a slab, a plane or a
        // cylinder's axis), and every seventh aimed at an object from any side (a cone's steep rays)
        std::vector<float> rays(size_t(7) * stride, 0.0f);
        for (int i = 0; i < stride; ++i) {
            for (int f = 0; f < 6; ++f) rays[size_t(f) * stride + i] = aos[6 * size_t(i % n) + f];
            if (i % 5 == 0)
                for (int f = 3; f < 6; ++f) rays[size_t(f) * stride + i] = f - 3 == (i / 5) % 3 ? ((i / 15) % 2 ? 1.0f : -1.0f) : 0.0f;
            if (i % 7 == 3) {
                const Vec3 target = anchors[size_t(i / 7) % anchors.size()] + 0.3f * Vec3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f);
                const Vec3 from = target + 2.5f * glm::normalize(Vec3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f) + Vec3(0.0f, 0.0f, 1e-3f));
                const Vec3 v = glm::normalize(target - from);
                const float ray[6] = {from.x, from.y, from.z, v.x, v.y, v.z};
                for (int f = 0; f < 6; ++f) rays[size_t(f) * stride + i] = ray[f];
            }
            rays[size_t(6) * stride + i] = i % 3 ? 100.0f : 4.0f * u01(rng);
        }
        lab::opencl::Program program =
            runtime.build(lab::kernels::assemble_scene_kernel("kernels/scene_exact_lanes_probe.cl", lab::scene::compile_scene(scene)),
                          std::string(lab::kernels::kSceneBuildOptions) + " -DSDF_LANES=8");
        lab::opencl::KernelHandle kernel = program.kernel("scene_exact_lanes_probe");
        lab::opencl::BufferHandle in = runtime.buffer(rays.size() * sizeof(float), CL_MEM_READ_ONLY);
        lab::opencl::BufferHandle lanes_out = runtime.buffer(size_t(stride) * sizeof(float), CL_MEM_WRITE_ONLY);
        lab::opencl::BufferHandle scalar_out = runtime.buffer(size_t(stride) * sizeof(float), CL_MEM_WRITE_ONLY);
        runtime.write(in, rays.data(), rays.size() * sizeof(float));
        lab::opencl::set_kernel_args(kernel, stride, in, lanes_out, scalar_out);
        runtime.launch_1d(kernel, size_t(stride / 8), 1);
        runtime.finish();
        std::vector<float> lanes_t(stride), scalar_t(stride);
        runtime.read(lanes_out, lanes_t.data(), lanes_t.size() * sizeof(float));
        runtime.read(scalar_out, scalar_t.data(), scalar_t.size() * sizeof(float));
        size_t hits = 0, short_hits = 0, differences = 0;
        for (int i = 0; i < stride; ++i) {
            uint32_t a, b;
            std::memcpy(&a, &lanes_t[i], 4);
            std::memcpy(&b, &scalar_t[i], 4);
            if (std::isfinite(scalar_t[i])) ++hits;
            if (i % 3 == 0 && std::isfinite(scalar_t[i])) ++short_hits;
            if (a != b) {
                ++differences;
                UNSCOPED_INFO(scene.file << " ray " << i << ": lane form " << std::setprecision(9) << lanes_t[i] << ", scalar form " << scalar_t[i]);
            }
        }
        std::printf("exact lane form: %-24s %d rays, %zu hits (%zu at a short t_max), %zu differences\n", scene.file.c_str(), stride, hits, short_hits,
                    differences);
        INFO(scene.file);
        CHECK(differences == 0);
        CHECK(hits >= size_t(stride) / 6);  // not a comparison of misses alone
    }
}

TEST_CASE("Exact intersection: the combined rule's edge cases", "[scene][exact]") {
    using namespace lab::render::host_kernels;
    const float eps_at_5 = march_epsilon(march_settings_default(1.0f), 5.0f);
    SECTION("an exact object inside a field object: the field's surface comes first from outside, the object from inside") {
        Scene scene = edge_scene(R"(
            {"name": "blob", "material": "m", "shape": {"type": "smooth_union", "radius": 0.2, "children": [
              {"type": "sphere", "radius": 1}, {"type": "translate", "offset": [0.9, 0, 0], "child": {"type": "sphere", "radius": 0.6}}]}},
            {"name": "core", "material": "m", "shape": {"type": "box", "half_size": [0.2, 0.2, 0.2]}}
          )", "inside.json");
        auto outside = host_ray(scene, Vec3(0.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f), 100.0f);
        REQUIRE(outside.status == MARCH_HIT);
        CHECK(outside.t <= 4.0f);
        CHECK(outside.t >= 4.0f - 2.0f * eps_at_5);  // the march's hit threshold, not the box at 4.8
        auto within = host_ray(scene, Vec3(0.0f, 0.0f, 0.7f), Vec3(0.0f, 0.0f, -1.0f), 100.0f);
        REQUIRE(within.status == MARCH_HIT);
        CHECK(std::fabs(within.t - 0.5f) <= 1e-6f);  // the box's face, exactly
    }
    SECTION("the camera inside an exact object: the ray leaves it where it should, and the field says inside") {
        Scene scene = edge_scene(R"(
            {"name": "shell", "material": "m", "shape": {"type": "translate", "offset": [0.5, 0, 0], "child": {"type": "sphere", "radius": 2}}},
            {"name": "field", "material": "m", "shape": {"type": "displace", "amplitude": 0.05, "frequency": 3,
              "child": {"type": "translate", "offset": [6, 0, 0], "child": {"type": "sphere", "radius": 1}}}}
          )", "camera_inside.json");
        auto r = host_ray(scene, Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), 100.0f);
        REQUIRE(r.status == MARCH_HIT);
        CHECK(std::fabs(r.t - 2.5f) <= 1e-6f);
        CHECK(lab::scene::scene_distance(scene, Vec3(0.0f)) < 0.0f);  // what the integrators' `inside` reads
    }
    SECTION("a march that stops at an exact hit: it does not march on to the field behind the wall") {
        Scene scene = edge_scene(R"(
            {"name": "wall", "material": "m", "shape": {"type": "plane", "normal": [0, 0, 1], "offset": 0}},
            {"name": "behind", "material": "m", "shape": {"type": "displace", "amplitude": 0.05, "frequency": 3,
              "child": {"type": "translate", "offset": [0, 0, -3], "child": {"type": "sphere", "radius": 1}}}},
            {"name": "front", "material": "m", "shape": {"type": "displace", "amplitude": 0.05, "frequency": 3,
              "child": {"type": "translate", "offset": [4, 0, 2], "child": {"type": "sphere", "radius": 1}}}}
          )", "wall.json");
        auto r = host_ray(scene, Vec3(0.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f), 100.0f);
        REQUIRE(r.status == MARCH_HIT);
        CHECK(std::fabs(r.t - 5.0f) <= 1e-6f);
        // the march alone, not stopped at the wall, goes on to the sphere behind it: more steps
        const lab::render::HostSceneScope scope(scene);
        MarchResult unstopped = march(Vec3(0.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, march_settings_default(1.0f));
        REQUIRE(unstopped.status == MARCH_HIT);
        CHECK(unstopped.t > 6.9f);
        CHECK(r.steps < unstopped.steps);
        // a field object in front of the wall is hit first
        auto front = host_ray(scene, Vec3(4.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f), 100.0f);
        REQUIRE(front.status == MARCH_HIT);
        CHECK(front.t < 2.2f);
    }
    SECTION("an over-relaxed step that leaps past the exact hit is checked before the march ends") {
        // from z = 5 the sphere's surface is 3.9 away: the first step of 1.5 x 3.9 ends past the wall
        // at 5, and the sphere in between must still be found
        Scene scene = edge_scene(R"(
            {"name": "wall", "material": "m", "shape": {"type": "plane", "normal": [0, 0, 1], "offset": 0}},
            {"name": "ball", "material": "m", "shape": {"type": "displace", "amplitude": 0.001, "frequency": 3,
              "child": {"type": "translate", "offset": [0, 0, 0.6], "child": {"type": "sphere", "radius": 0.5}}}}
          )", "leap.json");
        auto r = host_ray(scene, Vec3(0.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f), 100.0f, 1.5f);
        REQUIRE(r.status == MARCH_HIT);
        CHECK(r.t < 3.95f);
    }
}
