#include "kernels/host/brdf_batch.hpp"

#include <chrono>

#include "brdf/host/measured_registry.hpp"
#include "brdf/host/parameters.hpp"
#include "common/seconds_since.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "kernels/host/material_layout.hpp"

namespace lab::kernels {

using opencl::BufferHandle;
using opencl::KernelHandle;
using opencl::OpenClError;
using opencl::Program;
using opencl::Runtime;

namespace {

// Directions travel as packed float triples; glm::vec3 is exactly that.
static_assert(sizeof(brdf::float3) == 3 * sizeof(float), "brdf::float3 must be three packed floats");

using Clock = std::chrono::steady_clock;


Program timed_build(const Runtime& runtime, const std::string& options, double* seconds) {
    Clock::time_point start = Clock::now();
    Program program = build_embedded(runtime, "kernels/brdf_batch.cl", options);
    *seconds = seconds_since(start);
    return program;
}

}  // namespace

BrdfBatch::BrdfBatch(const Runtime& runtime, const std::string& extra_options)
    : runtime_(runtime),
      program_(timed_build(runtime, std::string(kBuildOptions) + (extra_options.empty() ? "" : " " + extra_options), &build_seconds_)),
      eval_(program_.kernel("brdf_eval")),
      pdf_(program_.kernel("brdf_pdf")),
      sample_(program_.kernel("brdf_sample")) {
    for (const KernelHandle* k : {&eval_, &pdf_, &sample_}) {
        size_t kernel_max = 0;
        opencl::check_cl(clGetKernelWorkGroupInfo(k->get(), runtime.device().device, CL_KERNEL_WORK_GROUP_SIZE, sizeof(kernel_max), &kernel_max, nullptr),
                         "clGetKernelWorkGroupInfo");
        while (local_size_ > 1 && local_size_ > kernel_max) local_size_ /= 2;
    }
    check_material_layout(runtime_, program_);

    // One item through every kernel, so later timings exclude PoCL's work-group compilation.
    Clock::time_point start = Clock::now();
    set_materials({brdf::default_material()});
    std::vector<int> index{0};
    std::vector<brdf::float3> wo{brdf::float3(0.0f, 0.0f, 1.0f)}, third{brdf::float3(0.5f, 0.5f, 0.5f)};
    eval(index, wo, third);
    pdf(index, wo, third);
    sample(index, wo, third);
    first_launch_seconds_ = seconds_since(start);
}

void BrdfBatch::set_materials(const std::vector<brdf::Material>& materials) {
    materials_ = runtime_.buffer(materials.size() * sizeof(brdf::Material), CL_MEM_READ_ONLY);
    runtime_.write(materials_, materials.data(), materials.size() * sizeof(brdf::Material));
    material_count_ = materials.size();
    // the BSDF's tables as the host has them now (brdf/bsdf_tables.h), so measured materials keep
    // their offsets and anisotropic ones find the energy table
    const std::vector<float>& tables = brdf::bsdf_table_data();
    tables_ = runtime_.buffer(tables.size() * sizeof(float), CL_MEM_READ_ONLY);
    runtime_.write(tables_, tables.data(), tables.size() * sizeof(float));
}

void BrdfBatch::check_inputs(const std::vector<int>& material, size_t wo_count, size_t third_count) const {
    if (wo_count != material.size() || third_count != material.size())
        throw OpenClError("BrdfBatch: " + std::to_string(material.size()) + " material indices but " + std::to_string(wo_count) +
                          " wo and " + std::to_string(third_count) + " wi/u");
    for (int index : material)
        if (index < 0 || size_t(index) >= material_count_)
            throw OpenClError("BrdfBatch: material index " + std::to_string(index) + " outside the " + std::to_string(material_count_) +
                              " materials set");
    if (material.size() > size_t(0x7fffffff)) throw OpenClError("BrdfBatch: batch too large for an int count");
}

void BrdfBatch::upload_inputs(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                              const std::vector<brdf::float3>& third, BufferHandle* index, BufferHandle* wo_buffer,
                              BufferHandle* third_buffer) {
    check_inputs(material, wo.size(), third.size());
    Clock::time_point start = Clock::now();
    size_t n = material.size();
    *index = runtime_.buffer(n * sizeof(int), CL_MEM_READ_ONLY);
    *wo_buffer = runtime_.buffer(n * sizeof(brdf::float3), CL_MEM_READ_ONLY);
    *third_buffer = runtime_.buffer(n * sizeof(brdf::float3), CL_MEM_READ_ONLY);
    runtime_.write(*index, material.data(), n * sizeof(int));
    runtime_.write(*wo_buffer, wo.data(), n * sizeof(brdf::float3));
    runtime_.write(*third_buffer, third.data(), n * sizeof(brdf::float3));
    timing_ = BatchTiming{};
    timing_.upload = seconds_since(start);
}

void BrdfBatch::run(const KernelHandle& kernel, size_t count) {
    Clock::time_point start = Clock::now();
    runtime_.launch_1d(kernel, count, local_size_);
    runtime_.finish();
    timing_.kernel = seconds_since(start);
}

std::vector<brdf::float3> BrdfBatch::eval(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                                          const std::vector<brdf::float3>& wi) {
    BufferHandle index, wo_buffer, wi_buffer;
    upload_inputs(material, wo, wi, &index, &wo_buffer, &wi_buffer);
    size_t n = material.size();
    BufferHandle f = runtime_.buffer(n * sizeof(brdf::float3), CL_MEM_WRITE_ONLY);
    opencl::set_kernel_args(eval_, int(n), materials_, tables_, index, wo_buffer, wi_buffer, f);
    run(eval_, n);
    Clock::time_point start = Clock::now();
    std::vector<brdf::float3> out(n);
    runtime_.read(f, out.data(), n * sizeof(brdf::float3));
    timing_.download = seconds_since(start);
    return out;
}

std::vector<float> BrdfBatch::pdf(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                                  const std::vector<brdf::float3>& wi) {
    BufferHandle index, wo_buffer, wi_buffer;
    upload_inputs(material, wo, wi, &index, &wo_buffer, &wi_buffer);
    size_t n = material.size();
    BufferHandle pdf = runtime_.buffer(n * sizeof(float), CL_MEM_WRITE_ONLY);
    opencl::set_kernel_args(pdf_, int(n), materials_, tables_, index, wo_buffer, wi_buffer, pdf);
    run(pdf_, n);
    Clock::time_point start = Clock::now();
    std::vector<float> out(n);
    runtime_.read(pdf, out.data(), n * sizeof(float));
    timing_.download = seconds_since(start);
    return out;
}

std::vector<brdf::BsdfSample> BrdfBatch::sample(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                                                const std::vector<brdf::float3>& u) {
    BufferHandle index, wo_buffer, u_buffer;
    upload_inputs(material, wo, u, &index, &wo_buffer, &u_buffer);
    size_t n = material.size();
    BufferHandle wi = runtime_.buffer(n * sizeof(brdf::float3), CL_MEM_WRITE_ONLY);
    BufferHandle f = runtime_.buffer(n * sizeof(brdf::float3), CL_MEM_WRITE_ONLY);
    BufferHandle pdf = runtime_.buffer(n * sizeof(float), CL_MEM_WRITE_ONLY);
    BufferHandle flags = runtime_.buffer(n * sizeof(int), CL_MEM_WRITE_ONLY);
    opencl::set_kernel_args(sample_, int(n), materials_, tables_, index, wo_buffer, u_buffer, wi, f, pdf, flags);
    run(sample_, n);
    Clock::time_point start = Clock::now();
    std::vector<brdf::float3> wi_out(n), f_out(n);
    std::vector<float> pdf_out(n);
    std::vector<int> flags_out(n);
    runtime_.read(wi, wi_out.data(), n * sizeof(brdf::float3));
    runtime_.read(f, f_out.data(), n * sizeof(brdf::float3));
    runtime_.read(pdf, pdf_out.data(), n * sizeof(float));
    runtime_.read(flags, flags_out.data(), n * sizeof(int));
    std::vector<brdf::BsdfSample> out(n);
    for (size_t i = 0; i < n; ++i) {
        out[i].wi = wi_out[i];
        out[i].f = f_out[i];
        out[i].pdf = pdf_out[i];
        out[i].flags = flags_out[i];
    }
    timing_.download = seconds_since(start);
    return out;
}

}  // namespace lab::kernels
