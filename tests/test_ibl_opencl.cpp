// The OpenCL build of ibl/environment.h (PoCL) against its C++ build: environment_radiance,
// environment_pdf and environment_sample on the same environment, directions and random numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "ibl/environment.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "validation/uniform_random.hpp"

using single_source::float3;

namespace {

// Directions travel as packed float triples (an OpenCL float3 buffer element is 16 bytes).
const char* kKernel = R"(#pragma OPENCL FP_CONTRACT OFF
#include "ibl/environment.h"

__kernel void environment_batch(int count, EnvironmentMap env, __global const float4* texels,
                                __global const AliasEntry* alias, __global const float* directions, __global const float* u,
                                __global float* radiance, __global float* pdf,
                                __global float* sampled, __global float* sampled_pdf) {
    int i = (int)get_global_id(0);
    if (i >= count) return;
    float3 d = (float3)(directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]);
    float3 l = environment_radiance(&env, texels, d);
    radiance[3 * i] = l.x;
    radiance[3 * i + 1] = l.y;
    radiance[3 * i + 2] = l.z;
    pdf[i] = environment_pdf(&env, texels, d);
    float p;
    float3 w = environment_sample(&env, texels, alias, u[2 * i], u[2 * i + 1], &p);
    sampled[3 * i] = w.x;
    sampled[3 * i + 1] = w.y;
    sampled[3 * i + 2] = w.z;
    sampled_pdf[i] = p;
}
)";

double relative(double a, double b) {
    if (a == b) return 0.0;
    return std::fabs(a - b) / std::fmax(std::fabs(a), std::fabs(b));
}

}  // namespace

TEST_CASE("ibl: the OpenCL build of environment.h agrees with the C++ build", "[ibl][opencl]") {
    lab::ibl::EnvironmentOptions options;
    options.face_size = 32;
    options.rotation_degrees = 33.0f;
    options.exposure_stops = 0.5f;
    const lab::ibl::Environment env = lab::ibl::load_environment("envmaps/sunset.exr", options);

    const int count = 20000;
    lab::validation::UniformRandom rng(1234);
    std::vector<float> directions(3 * count), u(2 * count);
    for (int i = 0; i < count; ++i) {
        const float3 d = glm::normalize(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        directions[3 * i] = d.x, directions[3 * i + 1] = d.y, directions[3 * i + 2] = d.z;
        u[2 * i] = rng.next_float(), u[2 * i + 1] = rng.next_float();
    }

    const std::string entry = "tests/ibl_environment_batch.cl";
    auto lookup = [&](const std::string& path) -> std::string_view {
        if (path == entry) return kKernel;
        return lab::kernels::embedded_kernel_file(path);
    };
    lab::opencl::Runtime runtime;
    const lab::opencl::Program program = runtime.build(lab::opencl::assemble_source(entry, lookup),
                                                       "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt");
    const lab::opencl::KernelHandle kernel = program.kernel("environment_batch");

    auto input = [&](const void* data, size_t bytes) {
        lab::opencl::BufferHandle b = runtime.buffer(bytes, CL_MEM_READ_ONLY);
        runtime.write(b, data, bytes);
        return b;
    };
    const auto texels = input(env.texels().data(), env.texels().size() * sizeof(single_source::float4));
    const auto alias = input(env.alias().data(), env.alias().size() * sizeof(lab::ibl::AliasEntry));
    const auto dir_buffer = input(directions.data(), directions.size() * sizeof(float));
    const auto u_buffer = input(u.data(), u.size() * sizeof(float));
    const auto radiance = runtime.buffer(3 * count * sizeof(float), CL_MEM_WRITE_ONLY);
    const auto pdf = runtime.buffer(count * sizeof(float), CL_MEM_WRITE_ONLY);
    const auto sampled = runtime.buffer(3 * count * sizeof(float), CL_MEM_WRITE_ONLY);
    const auto sampled_pdf = runtime.buffer(count * sizeof(float), CL_MEM_WRITE_ONLY);
    lab::opencl::set_kernel_arg(kernel, 0, count);
    lab::opencl::set_kernel_arg(kernel, 1, env.map());
    lab::opencl::set_kernel_arg(kernel, 2, texels);
    lab::opencl::set_kernel_arg(kernel, 3, alias);
    lab::opencl::set_kernel_arg(kernel, 4, dir_buffer);
    lab::opencl::set_kernel_arg(kernel, 5, u_buffer);
    lab::opencl::set_kernel_arg(kernel, 6, radiance);
    lab::opencl::set_kernel_arg(kernel, 7, pdf);
    lab::opencl::set_kernel_arg(kernel, 8, sampled);
    lab::opencl::set_kernel_arg(kernel, 9, sampled_pdf);
    runtime.launch_1d(kernel, count, 64);
    std::vector<float> cl_radiance(3 * count), cl_pdf(count), cl_sampled(3 * count), cl_sampled_pdf(count);
    runtime.read(radiance, cl_radiance.data(), cl_radiance.size() * sizeof(float));
    runtime.read(pdf, cl_pdf.data(), cl_pdf.size() * sizeof(float));
    runtime.read(sampled, cl_sampled.data(), cl_sampled.size() * sizeof(float));
    runtime.read(sampled_pdf, cl_sampled_pdf.data(), cl_sampled_pdf.size() * sizeof(float));

    // Lookups of the same direction read the same texel; a sampled direction may differ in the
    // last bits (normalize), which can move it across a texel edge: allowed for 1 in 10^4.
    int radiance_differs = 0, pdf_differs = 0, sample_differs = 0, sample_pdf_differs = 0;
    double worst_pdf = 0.0, worst_direction = 0.0;
    for (int i = 0; i < count; ++i) {
        const float3 d(directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]);
        const float3 l = env.radiance(d);
        radiance_differs += !(l == float3(cl_radiance[3 * i], cl_radiance[3 * i + 1], cl_radiance[3 * i + 2]));
        const double rp = relative(env.pdf(d), cl_pdf[i]);
        worst_pdf = std::fmax(worst_pdf, rp);
        pdf_differs += rp > 1e-5;
        float p;
        const float3 w = env.sample(u[2 * i], u[2 * i + 1], &p);
        const double dw = glm::length(w - float3(cl_sampled[3 * i], cl_sampled[3 * i + 1], cl_sampled[3 * i + 2]));
        worst_direction = std::fmax(worst_direction, dw);
        sample_differs += dw > 1e-5;
        sample_pdf_differs += relative(p, cl_sampled_pdf[i]) > 1e-5;
    }
    std::printf("[ibl] OpenCL vs C++ over %d items: radiance differs %d, pdf differs %d (worst relative %.2e), "
                "sampled direction worst %.2e (%d over 1e-5), sample pdf differs %d\n",
                count, radiance_differs, pdf_differs, worst_pdf, worst_direction, sample_differs, sample_pdf_differs);
    CHECK(radiance_differs == 0);
    CHECK(pdf_differs == 0);
    CHECK(sample_differs == 0);
    CHECK(sample_pdf_differs <= count / 10000);
}
