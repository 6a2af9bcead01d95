// The OpenCL build of the lights and the camera (kernels/lights/*.h, kernels/camera.h) against the
// C++ build: the headers compile as OpenCL C, and a tiny kernel calling every sampler on the same
// lights, points and random numbers returns what the host computes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "ibl/environment.hpp"
#include "kernels/host.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "render/camera_setup.hpp"
#include "render/light_set.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "validation/uniform_random.hpp"
#include "tests/worst_difference.hpp"

using brdf::float3;

namespace {

constexpr int kOutputs = 36;  // floats per item

const char* kKernel = R"(#pragma OPENCL FP_CONTRACT OFF
#include "kernels/camera.h"
#include "kernels/lights/light_selection.h"

static void put3(__global float* o, float3 v) { o[0] = v.x; o[1] = v.y; o[2] = v.z; }

__kernel void lights_batch(int count, int light_count, Camera camera, EnvironmentMap env,
                           __global const float4* texels, __global const AliasEntry* alias, __global const Light* lights, __global const float* cdf, __global const float* points,
                           __global const float* u, __global float* out) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    EnvironmentBuffers b;
    b.texels = texels;
    b.alias = alias;
    Light l = lights[i % light_count];
    float3 p = (float3)(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    __global const float* v = u + 6 * i;
    __global float* o = out + 36 * i;
    LightSample s = sample_light(&l, &env, b, p, (float2)(v[0], v[1]));
    put3(o, s.wi); o[3] = s.distance; put3(o + 4, s.radiance); o[7] = s.pdf; put3(o + 8, s.position); put3(o + 11, s.normal);
    o[14] = (float)s.delta;
    float3 w = normalize((float3)(v[2] - 0.5f, v[3] - 0.5f, v[4] - 0.5f));
    o[15] = light_pdf(&l, &env, b, p, w);
    float pmf;
    o[16] = (float)select_light(cdf, light_count, v[5], &pmf);
    o[17] = pmf;
    float3 origin, direction;
    camera_generate_ray(&camera, v[0] * camera.width, v[1] * camera.height, (float2)(v[2], v[3]), &origin, &direction);
    put3(o + 18, origin); put3(o + 21, direction);
    CameraSample c = camera_sample_wi(&camera, p, (float2)(v[4], v[5]));
    o[24] = c.raster.x; o[25] = c.raster.y; put3(o + 26, c.lens_point); put3(o + 29, c.wi);
    o[32] = c.distance; o[33] = c.importance; o[34] = c.pdf; o[35] = (float)c.visible;
}
)";

void put3(float* o, float3 v) {
    o[0] = v.x;
    o[1] = v.y;
    o[2] = v.z;
}

// The same on the host.
void host_item(int i, int light_count, const kernel::Camera& camera, const lab::ibl::Environment& env,
               const kernel::EnvironmentBuffers& b, const std::vector<kernel::Light>& lights, const std::vector<float>& cdf,
               const float* point, const float* v, float* o) {
    const kernel::Light l = lights[size_t(i % light_count)];
    const float3 p(point[0], point[1], point[2]);
    const kernel::LightSample s = kernel::sample_light(&l, &env.map(), b, p, kernel::make_float2(v[0], v[1]));
    put3(o, s.wi), o[3] = s.distance, put3(o + 4, s.radiance), o[7] = s.pdf, put3(o + 8, s.position), put3(o + 11, s.normal);
    o[14] = float(s.delta);
    const float3 w = glm::normalize(float3(v[2] - 0.5f, v[3] - 0.5f, v[4] - 0.5f));
    o[15] = kernel::light_pdf(&l, &env.map(), b, p, w);
    float pmf;
    o[16] = float(kernel::select_light(cdf.data(), light_count, v[5], &pmf));
    o[17] = pmf;
    float3 origin, direction;
    kernel::camera_generate_ray(&camera, v[0] * camera.width, v[1] * camera.height, kernel::make_float2(v[2], v[3]), &origin, &direction);
    put3(o + 18, origin), put3(o + 21, direction);
    const kernel::CameraSample c = kernel::camera_sample_wi(&camera, p, kernel::make_float2(v[4], v[5]));
    o[24] = c.raster.x, o[25] = c.raster.y, put3(o + 26, c.lens_point), put3(o + 29, c.wi);
    o[32] = c.distance, o[33] = c.importance, o[34] = c.pdf, o[35] = float(c.visible);
}

const char* kScene = R"({
  "camera": {"type": "thin_lens", "position": [0, 1, 5], "look_at": [0, 0.5, 0], "aperture_radius": 0.1, "focus_distance": 4},
  "materials": {"white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "box", "material": "white", "shape": {"type": "box", "half_size": [1, 1, 1]}}],
  "emitters": [
    {"center": [0, 2.5, 0], "radius": 0.4, "radiance": [5, 5, 5]},
    {"type": "point", "position": [1, 2, 3], "intensity": [2, 1, 1]},
    {"center": [-30, 10, -20], "radius": 0.05, "radiance": [100, 90, 80], "material": "white"}
  ]
})";

}  // namespace

TEST_CASE("lights OpenCL: the samplers and the camera agree with the C++ build", "[lights][opencl]") {
    const lab::scene::CompiledScene scene = lab::scene::compile_scene(lab::scene::parse_scene(kScene, "scenes/lights.json"));
    lab::ibl::EnvironmentOptions options;
    options.face_size = 16;
    options.rotation_degrees = -20.0f;
    const lab::ibl::Environment env = lab::ibl::load_environment("envmaps/courtyard.exr", options);
    const lab::render::LightSet set = lab::render::build_light_set(scene, &env, lab::render::LightSelection::power);
    const int light_count = int(set.lights.size());
    REQUIRE(light_count == 4);
    const kernel::Camera camera = lab::render::make_camera(scene.camera, 64, 48, scene.file);
    const kernel::EnvironmentBuffers b{env.texels().data(), env.alias().data()};

    const int count = 40000;
    lab::validation::UniformRandom rng(2718);
    std::vector<float> points(3 * size_t(count)), u(6 * size_t(count));
    for (int i = 0; i < count; ++i) {
        // around the scene, some inside the sphere light of radius 0.4 at (0, 2.5, 0)
        const bool inside = i % 7 == 0;
        const float3 p = inside ? float3(0.0f, 2.5f, 0.0f) + 0.35f * float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) / 1.8f
                                : float3(rng.uniform(-3, 3), rng.uniform(-1, 4), rng.uniform(-3, 3));
        put3(&points[3 * size_t(i)], p);
        for (int k = 0; k < 6; ++k) u[6 * size_t(i) + size_t(k)] = rng.next_float();
    }

    const std::string entry = "tests/lights_batch.cl";
    auto lookup = [&](const std::string& path) -> std::string_view {
        if (path == entry) return kKernel;
        return lab::kernels::embedded_kernel_file(path);
    };
    lab::opencl::Runtime runtime;
    const lab::opencl::Program program =
        runtime.build(lab::opencl::assemble_source(entry, lookup), "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt");
    const lab::opencl::KernelHandle kernel = program.kernel("lights_batch");
    auto input = [&](const void* data, size_t bytes) {
        lab::opencl::BufferHandle buffer = runtime.buffer(bytes, CL_MEM_READ_ONLY);
        runtime.write(buffer, data, bytes);
        return buffer;
    };
    const auto texels = input(env.texels().data(), env.texels().size() * sizeof(brdf::float4));
    const auto alias = input(env.alias().data(), env.alias().size() * sizeof(lab::ibl::AliasEntry));
    const auto lights = input(set.lights.data(), set.lights.size() * sizeof(kernel::Light));
    const auto cdf = input(set.selection_cdf.data(), set.selection_cdf.size() * sizeof(float));
    const auto point_buffer = input(points.data(), points.size() * sizeof(float));
    const auto u_buffer = input(u.data(), u.size() * sizeof(float));
    const auto out = runtime.buffer(size_t(kOutputs) * count * sizeof(float), CL_MEM_WRITE_ONLY);
    int arg = 0;
    lab::opencl::set_kernel_arg(kernel, arg++, count);
    lab::opencl::set_kernel_arg(kernel, arg++, light_count);
    lab::opencl::set_kernel_arg(kernel, arg++, camera);
    lab::opencl::set_kernel_arg(kernel, arg++, env.map());
    for (const auto* buffer : {&texels, &alias, &lights, &cdf, &point_buffer, &u_buffer, &out})
        lab::opencl::set_kernel_arg(kernel, arg++, *buffer);
    runtime.launch_1d(kernel, count, 64);
    std::vector<float> device(size_t(kOutputs) * count);
    runtime.read(out, device.data(), device.size() * sizeof(float));

    // Equal to float rounding: the scale of each quantity's own rounding, relative 2e-5 (points, pdfs,
    // importance; unit vectors and the raster absolute). An environment sample whose direction differs
    // in its last bits can cross a texel edge (a different pdf): allowed for 1 in 10^3 items.
    int differing = 0, exact_mismatch = 0;
    double worst = 0.0;
    std::vector<float> host(kOutputs);
    for (int i = 0; i < count; ++i) {
        host_item(i, light_count, camera, env, b, set.lights, set.selection_cdf, &points[3 * size_t(i)], &u[6 * size_t(i)], host.data());
        const float* d = &device[size_t(kOutputs) * i];
        double item = 0.0;
        for (int k = 0; k < kOutputs; ++k) {
            const double a = host[size_t(k)], c = d[k];
            if (k == 14 || k == 16 || k == 35) {  // delta, light index, visible: exact
                exact_mismatch += a != c;
                continue;
            }
            if (k == 3 && a == LIGHT_INFINITE_DISTANCE) {
                exact_mismatch += a != c;
                continue;
            }
            // unit vectors (wi, normal, ray direction, lens wi) and the raster on an absolute scale of 1
            const bool absolute = k <= 2 || (k >= 11 && k <= 13) || (k >= 21 && k <= 25) || (k >= 29 && k <= 31);
            const double scale = std::max({std::fabs(a), std::fabs(c), absolute ? 1.0 : 1e-3});
            item = worse_of(item, std::fabs(a - c) / scale);
        }
        worst = worse_of(worst, item);
        differing += !(item <= 2e-5);
    }
    std::printf("[lights] OpenCL against C++ over %d items: worst relative difference %.3g, %d items above 2e-5, %d exact fields differ\n",
                count, worst, differing, exact_mismatch);
    CHECK(exact_mismatch <= count / 1000);
    CHECK(differing <= count / 1000);
}
