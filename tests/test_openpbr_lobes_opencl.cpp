// The OpenPBR lobes (brdf/fresnel.h's F82 tint, brdf/eon_diffuse.h, brdf/thin_film.h) compiled as
// OpenCL C on PoCL against their C++ build: no model includes them yet, so this kernel is the one
// that shows they are written in the common subset, and that both builds agree to 1e-5 relative,
// the tolerance of the BSDF's agreement test (tests/test_opencl_agreement.cpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"

using brdf::float3;

namespace {

// Per item: wo, wi, rho (9 floats), sigma, tint, thickness; out: EON, F82 at wi, film RGB at wo over a
// dielectric and over a conductor (eta 0.2 + rho, kappa 3 rho).
constexpr int kLobeInputs = 12, kLobeOutputs = 12;

const char* const kLobeKernel = R"(
#pragma OPENCL FP_CONTRACT OFF
#include "single_source/vocabulary.h"
#include "brdf/fresnel.h"
#include "brdf/eon_diffuse.h"
#include "brdf/thin_film.h"

__kernel void openpbr_lobes(int count, __global const float* in, __global float* out) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    __global const float* p = in + 12 * i;
    float3 wo = (float3)(p[0], p[1], p[2]), wi = (float3)(p[3], p[4], p[5]), rho = (float3)(p[6], p[7], p[8]);
    float3 eon = eon_brdf(rho, p[9], wo, wi);
    float3 f82 = fresnel_f82_tint(rho, float3_splat(p[10]), wi.z);
    float3 film = thin_film_reflectance_rgb(wo.z, 1.0f, 1.2f + p[9], 1.5f, p[11]);
    float3 metal = thin_film_conductor_reflectance_rgb(wo.z, 1.0f, 1.2f + p[9], float3_splat(0.2f) + rho, 3.0f * rho, p[11]);
    __global float* o = out + 12 * i;
    o[0] = eon.x; o[1] = eon.y; o[2] = eon.z;
    o[3] = f82.x; o[4] = f82.y; o[5] = f82.z;
    o[6] = film.x; o[7] = film.y; o[8] = film.z;
    o[9] = metal.x; o[10] = metal.y; o[11] = metal.z;
}
)";

void lobes_on_host(const float* p, float* o) {
    float3 wo(p[0], p[1], p[2]), wi(p[3], p[4], p[5]), rho(p[6], p[7], p[8]);
    float3 values[4] = {brdf::eon_brdf(rho, p[9], wo, wi), brdf::fresnel_f82_tint(rho, float3(p[10]), wi.z),
                        brdf::thin_film_reflectance_rgb(wo.z, 1.0f, 1.2f + p[9], 1.5f, p[11]),
                        brdf::thin_film_conductor_reflectance_rgb(wo.z, 1.0f, 1.2f + p[9], float3(0.2f) + rho, 3.0f * rho, p[11])};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) o[3 * k + c] = values[k][c];
}

}  // namespace

TEST_CASE("OpenCL: the OpenPBR lobes agree with the C++ build", "[opencl][openpbr]") {
    const int count = 20000;
    std::mt19937 rng(37);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> in(size_t(count) * kLobeInputs);
    for (int i = 0; i < count; ++i) {
        float* p = &in[size_t(i) * kLobeInputs];
        float3 wo = brdf::square_to_cosine_hemisphere(u(rng), u(rng)), wi = brdf::square_to_uniform_sphere(u(rng), u(rng));
        if (i % 4 != 0) wi.z = std::fabs(wi.z);  // a quarter below the horizon
        float values[kLobeInputs] = {wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, u(rng), u(rng), u(rng),
                                     i % 10 == 0 ? 0.0f : u(rng), u(rng), i % 10 == 1 ? 0.0f : 2.0f * u(rng)};
        std::copy(values, values + kLobeInputs, p);
    }
    lab::opencl::SourceLookup lookup = [](const std::string& path) -> std::string_view {
        if (path == "tests/openpbr_lobes.cl") return kLobeKernel;
        return lab::kernels::embedded_kernel_file(path);
    };
    lab::opencl::Runtime runtime;
    lab::opencl::Program program = runtime.build(lab::opencl::assemble_source("tests/openpbr_lobes.cl", lookup),
                                                 "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt");
    lab::opencl::KernelHandle kernel = program.kernel("openpbr_lobes");
    lab::opencl::BufferHandle in_buffer = runtime.buffer(in.size() * sizeof(float), CL_MEM_READ_ONLY);
    lab::opencl::BufferHandle out_buffer = runtime.buffer(size_t(count) * kLobeOutputs * sizeof(float), CL_MEM_WRITE_ONLY);
    runtime.write(in_buffer, in.data(), in.size() * sizeof(float));
    lab::opencl::set_kernel_args(kernel, count, in_buffer, out_buffer);
    runtime.launch_1d(kernel, size_t(count), 64);
    std::vector<float> device(size_t(count) * kLobeOutputs);
    runtime.read(out_buffer, device.data(), device.size() * sizeof(float));

    double worst[4] = {0.0, 0.0, 0.0, 0.0};
    int failures = 0;
    std::string first_failure;
    for (int i = 0; i < count; ++i) {
        float host[kLobeOutputs];
        lobes_on_host(&in[size_t(i) * kLobeInputs], host);
        for (int k = 0; k < kLobeOutputs; ++k) {
            float a = host[k], b = device[size_t(i) * kLobeOutputs + k];
            double difference = a == b ? 0.0 : std::fabs(double(a) - b) / std::fmax(std::fabs(a), std::fabs(b));
            worst[k / 3] = std::fmax(worst[k / 3], difference);
            if (!(difference <= 1e-5) || !std::isfinite(b)) {
                if (failures++ == 0)
                    first_failure = "item " + std::to_string(i) + ", output " + std::to_string(k) + ": host " +
                                    std::to_string(a) + ", OpenCL " + std::to_string(b);
            }
        }
    }
    INFO(failures << " outputs differ; the first: " << first_failure);
    CHECK(failures == 0);
    std::printf("OpenPBR lobes, OpenCL against C++: largest relative difference EON %.1e, F82 %.1e, thin film %.1e, "
                "over a conductor %.1e\n", worst[0], worst[1], worst[2], worst[3]);
}
