// The SDF headers compiled as OpenCL C (PoCL) agree with their C++ build: every primitive,
// normal, domain operator and combinator at random points, and the marcher and normals on a test
// scene. The probe code below is written once and compiled both ways (SINGLE_SOURCE keeps its
// text for the kernel and compiles it for the host).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "kernels/host/embedded_sources.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "sdf/sdf.hpp"

// Defines the code for the host and keeps its spelling (before macro expansion) as a string.
#define SINGLE_SOURCE(name, ...)                \
    static const char* const name = #__VA_ARGS__; \
    __VA_ARGS__

namespace sdf_test_opencl {
using namespace sdf;

// clang-format off
SINGLE_SOURCE(kSceneSource,
SS_FN float scene_distance(float3 p) {
    float d = fPlane(p, make_float3(0.0f, 1.0f, 0.0f), 1.0f);
    d = fOpUnionSmooth(d, fSphere(p - make_float3(0.0f, 0.2f, 0.0f), 0.9f), 0.3f);
    d = fOpUnion(d, fOpSubtractionRound(fBox(p - make_float3(2.2f, -0.4f, 0.8f), make_float3(0.6f, 0.6f, 0.6f)),
                                        fCylinder(p - make_float3(2.2f, -0.4f, 0.8f), 0.3f, 1.0f), 0.05f));
    d = fOpUnion(d, fTorus(pModInterval3(p - make_float3(-2.0f, -0.5f, 0.0f), make_float3(0.0f, 0.0f, 1.6f),
                                         make_float3(0.0f, 0.0f, -1.0f), make_float3(0.0f, 0.0f, 1.0f)), 0.5f, 0.2f));
    return d;
}
SS_FN float scene_march_distance(float3 p) { return scene_distance(p); }
SS_FN int scene_analytic_normal(float3 p, float3* n) {
    if (p.x > 1.5f) return 0;
    *n = nSphere(p - make_float3(0.0f, 0.2f, 0.0f), 0.9f);
    return 1;
}
)
// clang-format on
#include "sdf/march.h"
#include "sdf/normals.h"

// clang-format off
SINGLE_SOURCE(kProbeSource,
SS_FN void put3(float* out, int* k, float3 v) {
    out[*k] = v.x;
    out[*k + 1] = v.y;
    out[*k + 2] = v.z;
    *k += 3;
}
SS_FN void put(float* out, int* k, float v) {
    out[*k] = v;
    *k += 1;
}
SS_FN int probe_point(float3 p, float* out) {
    int k = 0;
    float3 hs = make_float3(0.8f, 0.5f, 1.1f);
    put(out, &k, fSphere(p, 1.1f));             put3(out, &k, nSphere(p, 1.1f));
    float3 n = normalize(make_float3(0.3f, 1.0f, -0.2f));
    put(out, &k, fPlane(p, n, 0.4f));           put3(out, &k, nPlane(p, n, 0.4f));
    put(out, &k, fBox(p, hs));                  put3(out, &k, nBox(p, hs));
    put(out, &k, fRoundBox(p, hs, 0.2f));       put3(out, &k, nRoundBox(p, hs, 0.2f));
    put(out, &k, fTorus(p, 1.2f, 0.35f));       put3(out, &k, nTorus(p, 1.2f, 0.35f));
    put(out, &k, fCylinder(p, 0.7f, 0.9f));     put3(out, &k, nCylinder(p, 0.7f, 0.9f));
    put(out, &k, fCapsule(p, 0.4f, 0.8f));      put3(out, &k, nCapsule(p, 0.4f, 0.8f));
    put(out, &k, fCone(p, 0.9f, 1.6f));         put3(out, &k, nCone(p, 0.9f, 1.6f));
    put3(out, &k, pMod3(p, make_float3(1.3f, 0.0f, 0.7f)));
    put3(out, &k, pModInterval3(p, make_float3(1.3f, 0.9f, 0.7f), make_float3(-1.0f, 0.0f, -2.0f), make_float3(1.0f, 0.0f, 2.0f)));
    put3(out, &k, pMirror(p, n, 0.1f));
    float a = fSphere(p - make_float3(0.4f, 0.0f, 0.0f), 0.8f);
    float b = fBox(p + make_float3(0.3f, 0.1f, 0.0f), hs);
    put(out, &k, fOpUnion(a, b));               put(out, &k, fOpIntersection(a, b));
    put(out, &k, fOpSubtraction(a, b));         put(out, &k, fOpUnionSmooth(a, b, 0.4f));
    put(out, &k, fOpUnionRound(a, b, 0.3f));    put(out, &k, fOpIntersectionRound(a, b, 0.3f));
    put(out, &k, fOpSubtractionRound(a, b, 0.3f));
    put(out, &k, fOpUnionChamfer(a, b, 0.3f));  put(out, &k, fOpIntersectionChamfer(a, b, 0.3f));
    put(out, &k, fOpSubtractionChamfer(a, b, 0.3f));
    put(out, &k, fOpDisplaceSine(a, p, 0.1f, 7.0f));
    put(out, &k, lipschitz_round(1.0f, 1.5f));  put(out, &k, lipschitz_chamfer(1.0f, 1.5f));
    put(out, &k, lipschitz_displace_sine(1.2f, 0.1f, 7.0f));
    put(out, &k, scene_distance(p));
    put3(out, &k, normal_tetrahedral(p, 1e-3f));
    put3(out, &k, normal_central(p, 1e-3f));
    put3(out, &k, scene_normal(p, 1e-3f, NORMAL_ANALYTIC));
    return k;
}
SS_FN int probe_ray(float3 o, float3 d, float* out) {
    int k = 0;
    MarchSettings s = march_settings_default(1.0f);
    for (int pass = 0; pass < 2; ++pass) {
        s.over_relaxation = pass == 0 ? 1.0f : 1.5f;
        MarchResult r = march(o, d, 0.0f, s);
        put(out, &k, r.t);
        put(out, &k, (float)r.status);
        put(out, &k, (float)r.steps);
        put3(out, &k, scene_normal(o + d * r.t, 1e-3f, NORMAL_TETRAHEDRAL));
    }
    return k;
}
)
// clang-format on

}  // namespace sdf_test_opencl

namespace {

const int kPointValues = 65;
const int kRayValues = 12;

const char* const kKernel = R"(
#pragma OPENCL FP_CONTRACT OFF
#include "single_source/vocabulary.h"
#include "sdf/lipschitz.h"
#include "sdf/primitives/sphere.h"
#include "sdf/primitives/plane.h"
#include "sdf/primitives/box.h"
#include "sdf/primitives/round_box.h"
#include "sdf/primitives/torus.h"
#include "sdf/primitives/cylinder.h"
#include "sdf/primitives/capsule.h"
#include "sdf/primitives/cone.h"
#include "sdf/domain/mod3.h"
#include "sdf/domain/mod_interval3.h"
#include "sdf/domain/mirror.h"
#include "sdf/combinators/union.h"
#include "sdf/combinators/intersection.h"
#include "sdf/combinators/subtraction.h"
#include "sdf/combinators/union_smooth.h"
#include "sdf/combinators/union_round.h"
#include "sdf/combinators/intersection_round.h"
#include "sdf/combinators/subtraction_round.h"
#include "sdf/combinators/union_chamfer.h"
#include "sdf/combinators/intersection_chamfer.h"
#include "sdf/combinators/subtraction_chamfer.h"
#include "sdf/combinators/displace_sine.h"
#include "test/scene.h"
#include "sdf/march.h"
#include "sdf/normals.h"
#include "test/probe.h"

__kernel void sdf_probe_points(int count, __global const float* points, __global float* out) {
    int i = get_global_id(0);
    if (i >= count) return;
    float values[POINT_VALUES];
    int k = probe_point(make_float3(points[3 * i], points[3 * i + 1], points[3 * i + 2]), values);
    for (int j = 0; j < POINT_VALUES; ++j) out[i * POINT_VALUES + j] = j < k ? values[j] : NAN;
}

__kernel void sdf_probe_rays(int count, __global const float* rays, __global float* out) {
    int i = get_global_id(0);
    if (i >= count) return;
    float values[RAY_VALUES];
    float3 o = make_float3(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2]);
    float3 d = make_float3(rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5]);
    int k = probe_ray(o, d, values);
    for (int j = 0; j < RAY_VALUES; ++j) out[i * RAY_VALUES + j] = j < k ? values[j] : NAN;
}
)";

std::vector<float> run(const lab::opencl::Runtime& runtime, const lab::opencl::Program& program, const char* kernel_name,
                       const std::vector<float>& input, int count, int values) {
    lab::opencl::KernelHandle kernel = program.kernel(kernel_name);
    lab::opencl::BufferHandle in = runtime.buffer(input.size() * sizeof(float), CL_MEM_READ_ONLY);
    lab::opencl::BufferHandle out = runtime.buffer(size_t(count) * values * sizeof(float), CL_MEM_WRITE_ONLY);
    runtime.write(in, input.data(), input.size() * sizeof(float));
    lab::opencl::set_kernel_arg(kernel, 0, count);
    lab::opencl::set_kernel_arg(kernel, 1, in);
    lab::opencl::set_kernel_arg(kernel, 2, out);
    runtime.launch_1d(kernel, size_t(count), 64);
    std::vector<float> result(size_t(count) * values);
    runtime.read(out, result.data(), result.size() * sizeof(float));
    return result;
}

}  // namespace

TEST_CASE("SDF OpenCL: the headers compile as OpenCL C and agree with the C++ build", "[sdf][opencl]") {
    namespace t = sdf_test_opencl;
    const std::string scene = std::string("#ifndef TEST_SCENE_H\n#define TEST_SCENE_H\n") + t::kSceneSource + "\n#endif\n";
    const std::string probe = std::string("#ifndef TEST_PROBE_H\n#define TEST_PROBE_H\n") + t::kProbeSource + "\n#endif\n";
    auto lookup = [&](const std::string& path) -> std::string_view {
        if (path == "kernels/sdf_probe.cl") return kKernel;
        if (path == "test/scene.h") return scene;
        if (path == "test/probe.h") return probe;
        return lab::kernels::embedded_kernel_file(path);
    };
    lab::opencl::Runtime runtime;
    lab::opencl::AssembledSource source = lab::opencl::assemble_source("kernels/sdf_probe.cl", lookup);
    lab::opencl::Program program = runtime.build(source, "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt -DPOINT_VALUES=" +
                                                             std::to_string(kPointValues) + " -DRAY_VALUES=" + std::to_string(kRayValues));

    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    const int kPoints = 4000;
    std::vector<float> points(3 * kPoints);
    for (float& x : points) x = u(rng);
    std::vector<float> cl_points = run(runtime, program, "sdf_probe_points", points, kPoints, kPointValues);
    double worst = 0.0;
    int normal_mismatches = 0;
    for (int i = 0; i < kPoints; ++i) {
        float host[kPointValues];
        t::float3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
        REQUIRE(t::probe_point(p, host) == kPointValues);
        for (int j = 0; j < kPointValues; ++j) {
            float c = cl_points[size_t(i) * kPointValues + j];
            double diff = std::fabs(double(c) - host[j]) / std::fmax(1.0, std::fabs(double(host[j])));
            // the finite-difference normals (the last 9 values; the analytic one falls back to
            // tetrahedral for x > 1.5) divide rounding of f by h: ~1e-4
            bool finite_difference = j >= kPointValues - 9;
            if (finite_difference) {
                normal_mismatches += diff > 1e-3;
                continue;
            }
            worst = std::fmax(worst, diff);
            INFO("point " << i << " value " << j << ": C++ " << host[j] << ", OpenCL " << c);
            CHECK(diff <= 1e-5);
        }
    }

    const int kRays = 2000;
    std::vector<float> rays(6 * kRays);
    for (int i = 0; i < kRays; ++i) {
        t::float3 o(u(rng), 2.0f + 0.5f * u(rng), -6.0f);
        t::float3 target(u(rng), -0.5f, u(rng));
        t::float3 d = glm::normalize(target - o);
        for (int k = 0; k < 3; ++k) {
            rays[6 * i + k] = o[k];
            rays[6 * i + 3 + k] = d[k];
        }
    }
    std::vector<float> cl_rays = run(runtime, program, "sdf_probe_rays", rays, kRays, kRayValues);
    int status_mismatches = 0, step_mismatches = 0, hits = 0;
    double worst_t = 0.0;
    for (int i = 0; i < kRays; ++i) {
        float host[kRayValues];
        t::float3 o(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2]);
        t::float3 d(rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5]);
        REQUIRE(t::probe_ray(o, d, host) == kRayValues);
        const float* c = &cl_rays[size_t(i) * kRayValues];
        for (int pass = 0; pass < 2; ++pass) {
            const float* h = host + 6 * pass;
            const float* g = c + 6 * pass;
            status_mismatches += h[1] != g[1];
            step_mismatches += h[2] != g[2];
            if (h[1] == MARCH_HIT && g[1] == MARCH_HIT) {
                ++hits;
                worst_t = std::fmax(worst_t, std::fabs(double(h[0]) - g[0]) / std::fmax(1.0, double(h[0])));
            }
        }
    }
    std::printf("SDF OpenCL agreement on %s: %d points x %d values, worst relative difference %.3g (%d finite-difference "
                "normal components above 1e-3);\n  %d rays x 2 marches: %d status and %d step-count differences, "
                "worst t difference %.3g over %d hits\n",
                runtime.device().device_name.c_str(), kPoints, kPointValues, worst, normal_mismatches, kRays, status_mismatches,
                step_mismatches, worst_t, hits);
    CHECK(normal_mismatches <= kPoints / 100);
    CHECK(hits > kRays);
    CHECK(status_mismatches <= 2 * kRays / 200);
    CHECK(worst_t <= 1e-4);
}
