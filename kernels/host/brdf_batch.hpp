// The BRDF module run by OpenCL over arrays (kernels/brdf_batch.cl): bsdf_eval, bsdf_pdf and
// bsdf_sample for many (material, wo, wi or u) at once, with the host-side brdf types.
#pragma once

#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "opencl/runtime.hpp"

namespace lab::kernels {

// Wall-clock seconds of the last batch call, each phase finished before the next starts.
struct BatchTiming {
    double upload = 0.0;
    double kernel = 0.0;
    double download = 0.0;
};

class BrdfBatch {
public:
    // Without -cl-fast-relaxed-math: these kernels must agree with the C++ build.
    static constexpr const char* kBuildOptions = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

    // Builds the kernels (extra_options are appended, e.g. a -D that forces a cold build) and checks
    // that the device lays out Material like the host. Throws opencl::KernelBuildError or opencl::OpenClError.
    explicit BrdfBatch(const opencl::Runtime& runtime, const std::string& extra_options = "");

    // clBuildProgram, and the first launch of every kernel (PoCL compiles the work-group function then).
    double build_seconds() const { return build_seconds_; }
    double first_launch_seconds() const { return first_launch_seconds_; }

    void set_materials(const std::vector<brdf::Material>& materials);

    // Item i uses material[i] (an index into set_materials()), wo[i] and wi[i] (or u[i]).
    std::vector<brdf::float3> eval(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                                   const std::vector<brdf::float3>& wi);
    std::vector<float> pdf(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                           const std::vector<brdf::float3>& wi);
    std::vector<brdf::BsdfSample> sample(const std::vector<int>& material, const std::vector<brdf::float3>& wo,
                                         const std::vector<brdf::float3>& u);

    const BatchTiming& last_timing() const { return timing_; }

private:
    void check_inputs(const std::vector<int>& material, size_t wo_count, size_t third_count) const;
    void upload_inputs(const std::vector<int>& material, const std::vector<brdf::float3>& wo, const std::vector<brdf::float3>& third,
                       opencl::BufferHandle* index, opencl::BufferHandle* wo_buffer, opencl::BufferHandle* third_buffer);
    void run(const opencl::KernelHandle& kernel, size_t count);

    const opencl::Runtime& runtime_;
    double build_seconds_ = 0.0, first_launch_seconds_ = 0.0;  // before program_: its initialiser sets the first
    opencl::Program program_;
    opencl::KernelHandle eval_, pdf_, sample_;
    size_t local_size_ = 64;
    opencl::BufferHandle materials_;
    opencl::BufferHandle tables_;  // brdf::bsdf_table_data() when set_materials ran
    size_t material_count_ = 0;
    BatchTiming timing_;
};

}  // namespace lab::kernels
