// The display denoiser's passes (film/denoise.hpp) on an OpenCL device: the kernel of
// kernels/denoise.cl over buffers in the layout of film::AtrousBuffers, built once.
#pragma once

#include "film/denoise.hpp"
#include "opencl/runtime.hpp"

namespace lab::kernels {

class DeviceDenoiser {
public:
    // Builds kernels/denoise.cl. Throws opencl::KernelBuildError or opencl::OpenClError.
    explicit DeviceDenoiser(const opencl::Runtime& runtime);
    // As film::atrous_passes, on the device: the illumination in, filtered, back. With `cancelled`,
    // each pass is waited for before it is asked; false: it said so, and the buffers are unchanged.
    bool passes(film::AtrousBuffers* buffers, const film::DenoiseOptions& options, const film::FilterCancelled& cancelled = {}) const;

private:
    const opencl::Runtime& runtime_;
    opencl::Program program_;
    opencl::KernelHandle pass_;
};

}  // namespace lab::kernels
