// The compiled scene on an OpenCL device (kernels/scene_probe.cl, PoCL here) against the host
// interpreter (scene/interpreter.hpp): for every scene in scenes/ and the test scenes, at 10k random
// points, scene_distance_material agrees to 1e-5 (relative, or absolute below 1) with the same
// material slot, and scene_analytic_normal gives the same answer, except where two surfaces are
// equally near (a tie, where either choice is right). No device fails, not skips.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kernels/host/scene_kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "scene/compile.hpp"
#include "scene/interpreter.hpp"
#include "scene/load_scene.hpp"
#include "sdf/sdf.hpp"
#include "test_scene_points.hpp"

using lab::scene::CompiledScene;
using lab::scene::Scene;
using lab::scene::Vec3;

namespace {

constexpr double kTolerance = 1e-5;

struct ProbeResult {
    std::vector<float> distance;
    std::vector<int> material;
    std::vector<int> has_normal;
    std::vector<Vec3> normal;
};

ProbeResult run_probe(const lab::opencl::Runtime& runtime, const CompiledScene& scene, const std::vector<Vec3>& points) {
    static_assert(sizeof(Vec3) == 3 * sizeof(float), "points are uploaded as 3 floats each");
    lab::opencl::Program program = runtime.build(lab::kernels::assemble_scene_kernel("kernels/scene_probe.cl", scene),
                                                 lab::kernels::kSceneBuildOptions);
    lab::opencl::KernelHandle kernel = program.kernel("scene_probe");
    const size_t n = points.size();
    lab::opencl::BufferHandle in = runtime.buffer(n * sizeof(Vec3), CL_MEM_READ_ONLY);
    lab::opencl::BufferHandle distance = runtime.buffer(n * sizeof(float), CL_MEM_WRITE_ONLY);
    lab::opencl::BufferHandle material = runtime.buffer(n * sizeof(int), CL_MEM_WRITE_ONLY);
    lab::opencl::BufferHandle has_normal = runtime.buffer(n * sizeof(int), CL_MEM_WRITE_ONLY);
    lab::opencl::BufferHandle normal = runtime.buffer(n * sizeof(Vec3), CL_MEM_WRITE_ONLY);
    runtime.write(in, points.data(), n * sizeof(Vec3));
    lab::opencl::set_kernel_arg(kernel, 0, int(n));
    lab::opencl::set_kernel_arg(kernel, 1, in);
    lab::opencl::set_kernel_arg(kernel, 2, distance);
    lab::opencl::set_kernel_arg(kernel, 3, material);
    lab::opencl::set_kernel_arg(kernel, 4, has_normal);
    lab::opencl::set_kernel_arg(kernel, 5, normal);
    runtime.launch_1d(kernel, n, 64);
    runtime.finish();
    ProbeResult r{std::vector<float>(n), std::vector<int>(n), std::vector<int>(n), std::vector<Vec3>(n)};
    runtime.read(distance, r.distance.data(), n * sizeof(float));
    runtime.read(material, r.material.data(), n * sizeof(int));
    runtime.read(has_normal, r.has_normal.data(), n * sizeof(int));
    runtime.read(normal, r.normal.data(), n * sizeof(Vec3));
    return r;
}

// Whether the two nearest surfaces at p are equally near within the tolerance of both builds.
bool is_tie(const Scene& scene, Vec3 p) {
    std::vector<float> d;
    for (const auto& o : scene.objects) d.push_back(lab::scene::shape_distance(o.shape, p));
    for (const auto& e : scene.emitters) d.push_back(sdf::fSphere(p - e.center, e.radius));
    if (d.size() < 2) return false;
    std::partial_sort(d.begin(), d.begin() + 2, d.end());
    return double(d[1]) - double(d[0]) <= 2.0 * kTolerance * std::fmax(1.0, std::fabs(double(d[0])));
}

}  // namespace

TEST_CASE("scene OpenCL: compiled scenes agree with the host interpreter", "[scene][opencl]") {
    lab::opencl::Runtime runtime;  // throws (fails) when there is no device
    std::printf("scene OpenCL agreement on %s\n", runtime.device().description().c_str());
    const std::vector<Vec3> points = scene_test::random_points(10000, 2024);
    for (const std::string& file : scene_test::all_scene_files()) {
        Scene scene = lab::scene::load_scene(file);
        CompiledScene compiled = lab::scene::compile_scene(scene);
        ProbeResult cl = run_probe(runtime, compiled, points);
        double worst_distance = 0.0, worst_normal = 0.0;
        size_t distance_failures = 0, material_failures = 0, normal_failures = 0, ties = 0, analytic = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const Vec3 p = points[i];
            int material = -1;
            float d = lab::scene::scene_distance_material(scene, p, &material);
            Vec3 n(0.0f);
            int has_normal = lab::scene::scene_analytic_normal(scene, p, &n);
            double difference = std::fabs(double(d) - double(cl.distance[i])) / std::fmax(1.0, std::fmax(std::fabs(d), std::fabs(cl.distance[i])));
            worst_distance = std::fmax(worst_distance, difference);
            if (!(difference <= kTolerance)) {
                ++distance_failures;
                UNSCOPED_INFO(file << ": point (" << p.x << ", " << p.y << ", " << p.z << "): host " << d << ", OpenCL " << cl.distance[i]);
            }
            bool tie = is_tie(scene, p);
            ties += tie;
            if (tie) continue;
            if (material != cl.material[i]) {
                ++material_failures;
                UNSCOPED_INFO(file << ": point (" << p.x << ", " << p.y << ", " << p.z << "): host slot " << material << ", OpenCL slot "
                                   << cl.material[i]);
            }
            if (has_normal != cl.has_normal[i]) {
                ++normal_failures;
                continue;
            }
            if (!has_normal) continue;
            ++analytic;
            double e = glm::length(glm::dvec3(n) - glm::dvec3(cl.normal[i]));
            worst_normal = std::fmax(worst_normal, e);
            normal_failures += !(e <= 1e-4);
        }
        std::printf("scene OpenCL agreement: %-40s %zu points: worst distance difference %.2g, %zu ties, %zu analytic normals (worst %.2g)\n",
                    file.c_str(), points.size(), worst_distance, ties, analytic, worst_normal);
        INFO(file << ": worst distance difference " << worst_distance << ", worst normal difference " << worst_normal);
        CHECK(distance_failures == 0);
        CHECK(material_failures == 0);
        CHECK(normal_failures == 0);
        CHECK(ties < points.size() / 100);
    }
}
